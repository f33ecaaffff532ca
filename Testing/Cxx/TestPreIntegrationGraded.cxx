// Full pre-integration (Röttger et al. 2000) on a graded mesh: cell sizes spanning three decades.
//
// The 3D table's length axis is logarithmic (Kraus, Qiao & Ebert 2004, "Projecting Tetrahedra
// without Rendering Artifacts": a logarithmic scale for the pre-integrated lookup table), so a
// short cell next to long ones keeps its relative accuracy. Checked in three steps:
//  1. the axis as a plain function (psi::PreIntegrationLengthAxis): l = 0 exact, samples where
//     they should be, monotone, clamped, NaN-safe;
//  2. the table's lookup (trilinear, as the GPU filters) against the exact segment integral
//     (PsiReferenceIntegrals) for lengths from 1e-3 to 1 of the longest edge;
//  3. a graded slab (layers 0.005 to 5 thick) rendered with vtkPsiVolumeMapper and measured
//     against the exact CPU ray caster (PsiReferenceRaycaster), which also checks that the GLSL
//     coordinate matches the C++ one.
// Measured with the log axis: lookups within 0.0036 of the exact integral, image mean error
// 0.0013 and max 0.0041 (as partial pre-integration). With a linear axis (32 samples up to the
// longest edge) the thin layers turn nearly transparent: lookups off by 0.86 at D = 0.018, image
// mean error 0.0061 and max 0.70; every check of steps 2 and 3 fails.
//
// Usage: TestPreIntegrationGraded [output-dir]   (PNG images of GPU, reference and 8x difference)
#include "PsiIntegrationMethods.h"
#include "PsiPartialPreIntegrationTable.h"
#include "PsiPreIntegrationTable.h"
#include "PsiRampTable.h"
#include "PsiReferenceIntegrals.h"
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"
#include "PsiTransferFunctionTable.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkRectilinearGrid.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <limits>

namespace
{
constexpr int W = 96, H = 96;

void TestLengthAxis()
{
  const psi::PreIntegrationLengthAxis a = psi::MakePreIntegrationLengthAxis(0.005, 5.2);
  PSI_CHECK(a.Index(0) == 0 && a.Length(0) == 0, "l = 0 is sample 0 exactly");
  PSI_CHECK(a.Index(-1) == 0 && a.Index(std::numeric_limits<double>::quiet_NaN()) == 0,
    "negative and NaN lengths give sample 0");
  PSI_CHECK(
    std::abs(a.MinLength - 5.2e-4) < 1e-12, "l_min %g: a tenth of the shortest edge", a.MinLength);
  PSI_CHECK(a.Index(1e9) == a.Samples - 1 && a.Length(a.Samples - 1) == a.MaxLength,
    "longer than the longest edge clamps to the last sample");
  double worst = 0, last = -1;
  for (int k = 0; k < a.Samples; ++k)
  {
    worst = std::max(worst, std::abs(a.Index(a.Length(k)) - k));
  }
  bool monotone = true;
  for (double l = 1e-7; l < 10; l *= 1.01)
  {
    monotone = monotone && a.Index(l) >= last;
    last = a.Index(l);
  }
  PSI_CHECK(worst < 1e-9, "Index(Length(k)) = k within %g", worst);
  PSI_CHECK(monotone, "Index is monotone in l");
  // Geometric spacing: the same ratio between neighbouring samples.
  const double r1 = a.Length(2) / a.Length(1),
               r2 = a.Length(a.Samples - 1) / a.Length(a.Samples - 2);
  PSI_CHECK(std::abs(r1 - r2) < 1e-9 * r1, "geometric samples: ratio %g vs %g", r1, r2);
  // The shader form of the same function.
  float u[4];
  a.ShaderUniform(u);
  for (double l : { 1e-4, 5.2e-4, 0.01, 0.3, 5.2, 50.0 })
  {
    const double x = l * u[0];
    const double k = std::min(x < 1 ? x : 1 + std::log(x) * u[1], static_cast<double>(u[2]));
    PSI_CHECK(std::abs(k - a.Index(l)) < 1e-4, "shader form at l = %g: %g vs %g", l, k, a.Index(l));
  }
  // Bounds of l_min: four decades at most, two at least, below the longest edge.
  PSI_CHECK(psi::MakePreIntegrationLengthAxis(1e-9, 1).MinLength == 1e-4, "at most four decades");
  PSI_CHECK(psi::MakePreIntegrationLengthAxis(0.9, 1).MinLength == 1e-2, "at least two decades");
  PSI_CHECK(psi::MakePreIntegrationLengthAxis(0, 0).MaxLength == 1, "empty mesh: unit axis");
}

// Ramp transfer function: color and attenuation linear in s on [0, 1], tau up to tauMax.
psi::TransferFunctionTable Ramp(double tauMax)
{
  return psitest::RampTable({ 0, 0.5f, 1, 0 }, { 1, 0.5f, 0, static_cast<float>(tauMax) });
}

// Lookups against the exact integral for lengths from 1e-3 to 1 of the longest edge, with an
// attenuation that makes the short segments' optical depth about 1: the error is the table's.
void TestTableAccuracy()
{
  const double maxEdge = 5.2, tauMax = 200;
  const psi::TransferFunctionTable tf = Ramp(tauMax);
  const psi::PreIntegrationTable t = psi::BuildPreIntegrationTable(
    tf, psi::GetDefaultPsiTable(), psi::MakePreIntegrationLengthAxis(0.005, maxEdge));
  double worst = 0, worstAt = 0;
  for (double D = 0.005; D <= maxEdge; D *= 1.37)
  {
    for (double sf = 0.1; sf < 1; sf += 0.2)
    {
      for (double sb = 0.05; sb < 1; sb += 0.3)
      {
        psi::Segment g;
        g.Lf = { { sf, 0.5, 1 - sf } };
        g.Lb = { { sb, 0.5, 1 - sb } };
        g.tauf = tauMax * sf;
        g.taub = tauMax * sb;
        g.D = D;
        const psi::Rgba r = psi::IntegrateReference(g);
        double c[4];
        t.Lookup(sf, sb, D, c);
        for (int k = 0; k < 4; ++k)
        {
          if (std::abs(c[k] - r[k]) > worst)
          {
            worst = std::abs(c[k] - r[k]);
            worstAt = D;
          }
        }
      }
    }
  }
  std::printf("table lookup vs exact integral, lengths 0.005..5.2: max error %.5f (at D = %g)\n",
    worst, worstAt);
  PSI_CHECK(worst < 0.02, "table lookup error %g at D = %g", worst, worstAt);
  double zero[4];
  t.Lookup(0.3, 0.7, 0.0, zero);
  PSI_CHECK(zero[0] == 0 && zero[3] == 0, "D = 0 is transparent: %g %g", zero[0], zero[3]);
}

// Geometric coordinates: n cells from h0, each `ratio` times the last.
vtkSmartPointer<vtkDoubleArray> Graded(int n, double h0, double ratio)
{
  auto c = vtkSmartPointer<vtkDoubleArray>::New();
  double x = 0, h = h0;
  c->InsertNextValue(x);
  for (int i = 0; i < n; ++i, h *= ratio)
  {
    c->InsertNextValue(x += h);
  }
  return c;
}

// A slab 8 x 8 units wide whose 12 layers grow from 0.005 to 5 (three decades) in z, the thin
// layers facing the camera, split into tetrahedra; scalar smooth in x and y, slowly in z.
void MakeGradedSlab(vtkUnstructuredGrid* out)
{
  vtkNew<vtkRectilinearGrid> g;
  auto x = Graded(8, 1.0, 1.0), y = Graded(8, 1.0, 1.0);
  auto z = Graded(12, 0.005, std::pow(1000.0, 1.0 / 11));
  g->SetDimensions(9, 9, 13);
  g->SetXCoordinates(x);
  g->SetYCoordinates(y);
  g->SetZCoordinates(z);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType i = 0; i < g->GetNumberOfPoints(); ++i)
  {
    double p[3];
    g->GetPoint(i, p);
    s->InsertNextValue(0.5 + 0.35 * std::sin(0.7 * p[0]) * std::cos(0.5 * p[1]) - 0.01 * p[2]);
  }
  g->GetPointData()->SetScalars(s);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(g);
  tets->Update();
  out->ShallowCopy(tets->GetOutput());
}

void TestGradedSlabImage(const std::string& outDir)
{
  vtkNew<vtkUnstructuredGrid> grid;
  MakeGradedSlab(grid);
  double r[2];
  grid->GetPointData()->GetScalars()->GetRange(r);
  // Linear in RGB, opacity linear: the reference is exact, and partial pre-integration nearly so.
  // Unit distance 0.005: the thinnest layers have optical depth about 1, the thick ones are opaque.
  psitest::TransferFunction tf(0.005);
  psitest::BlueToYellow(tf.Color, r[0], r[1]);
  psitest::LinearOpacity(tf.Opacity, r[0], r[1], 0.1, 1.0);
  const psi::ReferenceScene ref = psitest::MakeReferenceScene(grid, tf.Color, tf.Opacity, 0.005);

  vtkNew<vtkPsiVolumeMapper> mapper;
  mapper->SetInputData(grid);
  psitest::VolumeView view(W, H, mapper, tf.Property);
  vtkRenderWindow* win = view.Window;
  vtkRenderer* ren = view.Renderer;
  vtkVolume* vol = view.Volume;
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(4, 4, 0);
  cam->SetPosition(1.5, 2.5, -14);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  ren->ResetCameraClippingRange();

  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::PartialPreIntegration));
  const psitest::Result partial =
    psitest::Compare("graded_partial", win, ren, vol, ref, nullptr, outDir);
  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::FullPreIntegration));
  const psitest::Result full = psitest::Compare("graded_full", win, ren, vol, ref, nullptr, outDir);
  PSI_CHECK(partial.Covered > W * H / 3, "graded slab: image nearly empty (%d)", partial.Covered);
  PSI_CHECK(
    partial.Mean < 0.004, "graded slab, partial pre-integration: mean error %g", partial.Mean);
  PSI_CHECK(full.Mean < 0.003 && full.Max < 0.05,
    "graded slab, full pre-integration: mean error %g, max %g", full.Mean, full.Max);
}
} // namespace

int main(int argc, char* argv[])
{
  TestLengthAxis();
  TestTableAccuracy();
  TestGradedSlabImage(argc > 1 ? argv[1] : "");
  return psitest::Report("TestPreIntegrationGraded");
}
