// Renders small tetrahedral meshes with vtkPsiVolumeMapper and measures the image against the
// exact CPU ray integration (PsiReferenceRaycaster) of the same mesh, transfer function and
// camera: perspective and parallel projection, a camera inside the mesh, opaque geometry cutting
// through the volume, and each integration method. Needs an X server (run under xvfb-run).
//
// Usage: TestPsiVolumeRender [output-dir]   (PNG images of GPU, reference and 8x difference)
#include "PsiIntegrationMethods.h"
#include "PsiReferenceRaycaster.h"
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"
#include "PsiVisibilityOrder.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
constexpr int W = 96, H = 96;

// A mesh and its transfer function.
struct Scene : psitest::TransferFunction
{
  vtkNew<vtkUnstructuredGrid> Grid;
};

// The Wavelet source on [-half, half]^3, cells scaled to `cell` units, split into tetrahedra
// (by vtkDataSetTriangleFilter, or into Kuhn tetrahedra).
void MakeScene(
  Scene& s, int half, double cell, double unitDistance, bool linearTF = false, bool kuhn = false)
{
  if (kuhn)
  {
    psitest::MakeKuhnWavelet(s.Grid, half, cell);
  }
  else
  {
    psitest::MakeWaveletTets(s.Grid, half, cell);
  }
  double r[2];
  s.Grid->GetPointData()->GetScalars()->GetRange(r);
  s.Property->SetScalarOpacityUnitDistance(unitDistance);
  if (linearTF)
  {
    // One linear piece: the GPU's per-cell linear transfer function is then exact, and what is
    // left is the ray integration itself.
    psitest::BlueToYellow(s.Color, r[0], r[1]);
    psitest::LinearOpacity(s.Opacity, r[0], r[1], 0.02, 1.0);
    return;
  }
  // Linear-in-RGB color map and a ramp with a peak: control points are the reference's
  // breakpoints, so the reference is exact for this transfer function.
  psitest::BlueWhiteRed(s.Color, r[0], r[1]);
  s.Opacity->AddPoint(r[0], 0.0);
  s.Opacity->AddPoint(r[0] + 0.6 * (r[1] - r[0]), 0.35);
  s.Opacity->AddPoint(r[1], 0.9);
}

psi::ReferenceScene MakeReference(Scene& s)
{
  return psitest::MakeReferenceScene(s.Grid, s);
}

// What the checks draw: the Wavelet on [-6, 6]^3 and its reference, the mapper and its view.
struct Fixture
{
  std::string OutDir;
  Scene S;
  psi::ReferenceScene Ref;
  vtkNew<vtkPsiVolumeMapper> Mapper;
  psitest::VolumeView View{ W, H, Mapper, S.Property };

  explicit Fixture(const std::string& outDir)
    : OutDir(outDir)
  {
    psitest::ApplyRequested(this->Mapper.GetPointer());
    MakeScene(this->S, 6, 1.0, 1.5);
    this->Ref = MakeReference(this->S);
    this->Mapper->SetInputData(this->S.Grid);
  }

  // The image against the reference `ref` (psitest::Compare), with `opaque` geometry.
  psitest::Result Compare(
    const std::string& name, const psi::ReferenceScene& ref, vtkActor* opaque = nullptr)
  {
    return psitest::Compare(
      name, this->View.Window, this->View.Renderer, this->View.Volume, ref, opaque, this->OutDir);
  }

  // Draws `s` instead of the Wavelet on [-6, 6]^3 (nullptr: that one again).
  void Draw(Scene* s)
  {
    this->Mapper->SetInputData(s ? s->Grid : this->S.Grid);
    this->View.Volume->SetProperty(s ? s->Property : this->S.Property);
  }
};

void Outside(Fixture& f)
{
  psitest::LookAtCentre(f.View.Renderer, 21, 14, 29);
}

// Each method in perspective, from outside, with an empty actor in the scene.
void CheckPerspectiveMethods(Fixture& f)
{
  vtkPsiVolumeMapper* mapper = f.Mapper;
  vtkRenderer* ren = f.View.Renderer;
  // Per-scenario bounds on the mean absolute error (8-bit channels in [0, 1]); measured values
  // are printed, and the bounds sit well below what a wrong thickness, order or scalar gives.
  struct Case
  {
    const char* Name;
    int Method;
    double MeanBound, MaxBound;
  };
  Outside(f);
  // An actor with nothing to draw (ParaView keeps one for each representation not shown) has
  // uninitialized bounds: it is not opaque geometry and must not turn on depth sampling.
  vtkNew<vtkPolyDataMapper> emptyMapper;
  vtkNew<vtkPolyData> emptyPolyData;
  emptyMapper->SetInputData(emptyPolyData);
  vtkNew<vtkActor> emptyActor;
  emptyActor->SetMapper(emptyMapper);
  ren->AddActor(emptyActor);
  for (const Case& k :
    { Case{
        "perspective_partial", static_cast<int>(psi::Method::PartialPreIntegration), 0.006, 0.03 },
      Case{ "perspective_average", static_cast<int>(psi::Method::Average), 0.02, 0.03 },
      Case{ "perspective_full", static_cast<int>(psi::Method::FullPreIntegration), 0.006, 0.015 } })
  {
    mapper->SetIntegrationMethod(k.Method);
    const psitest::Result r = f.Compare(k.Name, f.Ref);
    PSI_CHECK(r.Mean < k.MeanBound && r.Max < k.MaxBound, "%s: mean error %g, max %g", k.Name,
      r.Mean, r.Max);
    PSI_CHECK(r.Covered > W * H / 8, "%s: image nearly empty (%d pixels)", k.Name, r.Covered);
  }
  PSI_CHECK(mapper->GetNumberOfTetrahedra() == f.S.Grid->GetNumberOfCells(),
    "tetrahedra drawn %lld", static_cast<long long>(mapper->GetNumberOfTetrahedra()));
  PSI_CHECK(!mapper->GetLastUsedNearPlaneClipping(), "outside view must not compile the near path");
  PSI_CHECK(!mapper->GetLastUsedOpaqueClipping(), "no opaque geometry: no depth sampling");
  ren->RemoveActor(emptyActor);
  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::PartialPreIntegration));
}

// Visibility order on Kuhn cells seen head-on (the view that showed lines in the GUI test): the
// centroid order composites some neighbours in the wrong order, MPVONC is exact.
void CheckKuhnCellsOrder(Fixture& f)
{
  vtkPsiVolumeMapper* mapper = f.Mapper;
  vtkCamera* cam = f.View.Renderer->GetActiveCamera();
  Scene kuhn;
  MakeScene(kuhn, 2, 4.0, 0.3, true, true);
  const psi::ReferenceScene kuhnRef = MakeReference(kuhn);
  f.Draw(&kuhn);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetPosition(0.3, 0.2, 45);
  f.View.Renderer->ResetCameraClippingRange();
  mapper->SetSortMethod(psi::Sorts::Centroid);
  const psitest::Result centroid = f.Compare("kuhn_centroid", kuhnRef);
  mapper->SetSortMethod(psi::Sorts::MPVONC);
  const psitest::Result mpvonc = f.Compare("kuhn_mpvonc", kuhnRef);
  PSI_CHECK(mpvonc.Max < 0.03 && mpvonc.Mean < 0.003, "Kuhn cells, MPVONC: mean %g max %g",
    mpvonc.Mean, mpvonc.Max);
  PSI_CHECK(centroid.Max > 2 * mpvonc.Max, "Kuhn cells: centroid order max %g vs MPVONC %g",
    centroid.Max, mpvonc.Max);
  f.Draw(nullptr);
  Outside(f);
}

// A new time step of the same mesh: a new dataset sharing the points and cells (as ParaView's
// representations hand it over), with new scalars. Only the scalars are uploaded again: the mesh
// is not gathered again (nor sorted), and the image is the new scalars' reference.
void CheckTimeStep(Fixture& f)
{
  vtkPsiVolumeMapper* mapper = f.Mapper;
  f.View.Window->Render();
  const int version = mapper->GetMeshVersion();
  vtkNew<vtkUnstructuredGrid> step;
  step->ShallowCopy(f.S.Grid);
  vtkNew<vtkFloatArray> scaled;
  vtkDataArray* rt = f.S.Grid->GetPointData()->GetScalars();
  scaled->SetName(rt->GetName());
  scaled->SetNumberOfTuples(rt->GetNumberOfTuples());
  for (vtkIdType i = 0; i < rt->GetNumberOfTuples(); ++i)
  {
    scaled->SetValue(i, static_cast<float>(1.1 * rt->GetComponent(i, 0)));
  }
  step->GetPointData()->SetScalars(scaled);
  mapper->SetInputData(step);
  const psitest::Result r =
    f.Compare("time_step", psitest::MakeReferenceScene(step, f.S.Color, f.S.Opacity, 1.5));
  PSI_CHECK(mapper->GetMeshVersion() == version, "a time step gathered the mesh again");
  PSI_CHECK(r.Mean < 0.006 && r.Max < 0.05, "time step: mean error %g, max %g", r.Mean, r.Max);
  mapper->SetInputData(f.S.Grid);
}

// A mesh of five draw chunks or more (PsiVisibilityOrder::Draw streams chunks of 4,096
// tetrahedra where cells are small for the target, else 32,768, at most 2 in flight): every
// chunk is drawn, in order, after the waits, with either chunk size.
void CheckFiveChunks(Fixture& f)
{
  Scene fine;
  MakeScene(fine, 16, 0.375, 1.5);
  const psi::ReferenceScene fineRef = MakeReference(fine);
  f.Draw(&fine);
  const size_t n = static_cast<size_t>(fine.Grid->GetNumberOfCells());
  for (const int side : { W, 232 })
  {
    f.View.Window->SetSize(side, side);
    const size_t chunk = PsiVisibilityOrder::ChunkTetsFor(n, size_t(side) * side);
    const psitest::Result r = f.Compare("five_chunks_" + std::to_string(chunk), fineRef);
    PSI_CHECK(n > 4 * chunk && chunk == (side == W ? 4096u : 32768u),
      "five chunks: %zu tetrahedra in chunks of %zu", n, chunk);
    // (at 232^2 Shirley-Tuchman's fan, --decomposition fan, leaves one stray pixel at 0.15)
    PSI_CHECK(r.Mean < 0.006 && (side == W ? r.Max : r.P999) < 0.05 && r.Outliers < 1e-4,
      "five chunks of %zu: mean error %g, max %g, 99.9%% %g", chunk, r.Mean, r.Max, r.P999);
  }
  f.View.Window->SetSize(W, H);
  f.Draw(nullptr);
}

// Parallel projection.
void CheckParallel(Fixture& f)
{
  f.View.Renderer->GetActiveCamera()->SetParallelProjection(1);
  f.View.Renderer->ResetCamera();
  const psitest::Result r = f.Compare("parallel_partial", f.Ref);
  PSI_CHECK(r.Mean < 0.006, "parallel: mean error %g", r.Mean);
  PSI_CHECK(r.Covered > W * H / 8, "parallel: image nearly empty");
}

// Camera inside the mesh: tetrahedra cut by the near plane are clipped, not dropped.
void CheckCameraInside(Fixture& f)
{
  vtkPsiVolumeMapper* mapper = f.Mapper;
  psitest::SetCameraInside(f.View.Renderer->GetActiveCamera());
  const psitest::Result r = f.Compare("camera_inside", f.Ref);
  PSI_CHECK(mapper->GetLastUsedNearPlaneClipping(), "inside view must use the near-plane path");
  PSI_CHECK(r.Mean < 0.003 && r.Max < 0.02, "camera inside: mean error %g max %g", r.Mean, r.Max);
  PSI_CHECK(r.Covered > W * H / 2, "camera inside: image should be covered (%d)", r.Covered);
  // HAPT's screen-linear thickness is visibly wrong for cells close to the eye; the exact
  // per-fragment reconstruction is what makes the inside view correct.
  // (silhouettes are exact in both projections: the screen-linear triple is the fan's)
  const int decomposition = mapper->GetDecomposition();
  mapper->SetDecomposition(psi::Decompositions::Fan);
  mapper->ExactPerspectiveSegmentsOff();
  const psitest::Result linear = f.Compare("camera_inside_screen_linear", f.Ref);
  mapper->ExactPerspectiveSegmentsOn();
  mapper->SetDecomposition(decomposition);
  PSI_CHECK(r.Max < 0.25 * linear.Max, "exact segments max error %g vs screen-linear %g", r.Max,
    linear.Max);
}

// The same inside view in a parallel projection. In perspective the vertices behind the eye
// project off screen and hide a wrong screen box of a clipped cell; here they project onto it.
void CheckCameraInsideParallel(Fixture& f)
{
  vtkCamera* cam = f.View.Renderer->GetActiveCamera();
  cam->SetParallelProjection(1);
  cam->SetParallelScale(2.0);
  const psitest::Result r = f.Compare("camera_inside_parallel", f.Ref);
  PSI_CHECK(f.Mapper->GetLastUsedNearPlaneClipping(), "parallel inside view: near-plane path");
  PSI_CHECK(r.Mean < 0.003 && r.Max < 0.02 && r.Covered > W * H / 2,
    "camera inside, parallel: mean error %g max %g, %d pixels covered", r.Mean, r.Max, r.Covered);
}

// Camera inside, and an opaque square just beyond the near plane, in front of cells that the near
// plane cuts: their rays enter those cells behind the square, so the scene-depth test of the
// clipped segment's front (the screen box itself is drawn on the near plane) must hide them.
void CheckCameraInsideOpaque(Fixture& f)
{
  vtkRenderer* ren = f.View.Renderer;
  vtkCamera* cam = ren->GetActiveCamera();
  psitest::SetCameraInside(cam);
  vtkNew<vtkPlaneSource> square;
  double c[3], d[3], p[3];
  cam->GetPosition(p);
  cam->GetDirectionOfProjection(d);
  for (int k = 0; k < 3; ++k)
  {
    c[k] = p[k] + 0.4 * d[k];
  }
  square->SetCenter(c);
  square->SetNormal(d);
  vtkNew<vtkPolyDataMapper> squareMapper;
  squareMapper->SetInputConnection(square->GetOutputPort());
  vtkNew<vtkActor> near;
  near->SetMapper(squareMapper);
  near->GetProperty()->LightingOff();
  near->GetProperty()->SetColor(0.2, 0.7, 0.3);
  near->SetScale(0.25);
  near->SetOrigin(c);
  ren->AddActor(near);
  const psitest::Result r = f.Compare("camera_inside_opaque", f.Ref, near);
  PSI_CHECK(f.Mapper->GetLastUsedNearPlaneClipping() && f.Mapper->GetLastUsedOpaqueClipping(),
    "inside view with opaque geometry: near-plane and opaque paths");
  PSI_CHECK(r.Mean < 0.003 && r.Max < 0.03, "camera inside, opaque square: mean error %g max %g",
    r.Mean, r.Max);
  ren->RemoveActor(near);
}

// Opaque geometry through the middle of the volume: hides what is behind it, and the cells it
// cuts are integrated only up to it.
void CheckOpaquePlane(Fixture& f)
{
  vtkRenderer* ren = f.View.Renderer;
  Outside(f);
  vtkSmartPointer<vtkActor> actor = psitest::MakeOpaquePlane(9);
  ren->AddActor(actor);
  ren->ResetCameraClippingRange();
  const psitest::Result r = f.Compare("opaque_plane", f.Ref, actor);
  PSI_CHECK(r.Mean < 0.006, "opaque geometry: mean error %g", r.Mean);
  PSI_CHECK(f.Mapper->GetLastUsedOpaqueClipping(), "opaque plane in the volume needs clipping");
  ren->RemoveActor(actor);
}

// Coarse cells: tau D reaches several units and color changes across a cell, where averaging is
// wrong and partial pre-integration is not (transfer function linear, see MakeScene).
void CheckCoarseCells(Fixture& f)
{
  vtkPsiVolumeMapper* mapper = f.Mapper;
  vtkRenderer* ren = f.View.Renderer;
  Scene coarse;
  MakeScene(coarse, 3, 3.0, 1.0, true);
  const psi::ReferenceScene coarseRef = MakeReference(coarse);
  f.Draw(&coarse);
  psitest::LookAtCentre(ren, 25, 17, 35);
  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::Average));
  const psitest::Result avg = f.Compare("coarse_average", coarseRef);
  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::PartialPreIntegration));
  const psitest::Result ppi = f.Compare("coarse_partial", coarseRef);
  // Röttger et al. 2000 §4 with its table's sub-segments composited front to back: over coarse
  // cells the color changes along each segment, and the order of the pieces shows.
  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::FullPreIntegration));
  const psitest::Result full = f.Compare("coarse_full", coarseRef);
  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::PartialPreIntegration));
  // Means sit near the 8-bit quantization floor (~0.001) for both; the worst pixel tells them
  // apart.
  PSI_CHECK(
    ppi.Max < 0.5 * avg.Max, "partial pre-integration max %g vs average %g", ppi.Max, avg.Max);
  PSI_CHECK(ppi.Max < 0.01 && ppi.Mean < 0.002, "coarse partial pre-integration error %g / %g",
    ppi.Mean, ppi.Max);
  PSI_CHECK(full.Max < 0.01 && full.Mean < 0.002, "coarse full pre-integration error %g / %g",
    full.Mean, full.Max);
  // The opaque plane through coarse cells: each cut segment ends at the plane with the scalar
  // there (the scalar is linear along the ray, so it is interpolated to the cut).
  vtkSmartPointer<vtkActor> cutPlane = psitest::MakeOpaquePlane(9);
  ren->AddActor(cutPlane);
  ren->ResetCameraClippingRange();
  const psitest::Result cut = f.Compare("coarse_opaque", coarseRef, cutPlane);
  ren->RemoveActor(cutPlane);
  PSI_CHECK(cut.Max < 0.01 && cut.Mean < 0.002, "coarse cells cut by an opaque plane: %g / %g",
    cut.Mean, cut.Max);
}

// The largest difference (of 255) between the image drawn with early discard and without it.
int EarlyDiscardChange(Fixture& f)
{
  vtkRenderWindow* win = f.View.Window;
  vtkNew<vtkUnsignedCharArray> a, b;
  win->GetPixelData(0, 0, W - 1, H - 1, 0, a);
  f.Mapper->EarlyDiscardOff();
  win->Render();
  win->GetPixelData(0, 0, W - 1, H - 1, 0, b);
  f.Mapper->EarlyDiscardOn();
  int maxDiff = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    maxDiff = std::max(maxDiff, std::abs(int(a->GetValue(i)) - int(b->GetValue(i))));
  }
  return maxDiff;
}

// HAPT §3.5 early discard: with zero opacity over the lower half of the scalar range, the
// tetrahedra that only see that half are dropped in the geometry shader; the image must not
// change, and the variant is compiled only when the opacity function has a zero region.
void CheckEarlyDiscard(Fixture& f)
{
  vtkPsiVolumeMapper* mapper = f.Mapper;
  Scene& s = f.S;
  f.Draw(nullptr);
  Outside(f);
  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::PartialPreIntegration));
  f.View.Window->Render();
  PSI_CHECK(!mapper->GetLastUsedEarlyDiscard(), "no zero-opacity region: no early discard");
  double r[2];
  s.Grid->GetPointData()->GetScalars()->GetRange(r);
  vtkNew<vtkPiecewiseFunction> saved;
  saved->DeepCopy(s.Opacity);
  s.Opacity->RemoveAllPoints(); // in place: the reference reads the same function
  s.Opacity->AddPoint(r[0], 0.0);
  s.Opacity->AddPoint(0.5 * (r[0] + r[1]), 0.0);
  s.Opacity->AddPoint(r[1], 0.8);
  const psitest::Result with = f.Compare("early_discard", MakeReference(s));
  PSI_CHECK(mapper->GetLastUsedEarlyDiscard(), "zero-opacity region: early discard compiled in");
  int maxDiff = EarlyDiscardChange(f);
  PSI_CHECK(maxDiff == 0, "early discard changed the image (max %d/255)", maxDiff);
  PSI_CHECK(with.Mean < 0.006, "early discard scene vs reference: mean error %g", with.Mean);

  // A coarse table (16 samples) with the opacity rising from zero over one sample interval: a
  // cell whose scalar range ends inside that interval, or meets a single non-zero sample, sees a
  // visible opacity there, and early discard must keep it (the test of the samples that bracket
  // the cell's range, Maximo et al. 2010 §3.5).
  mapper->SetTransferFunctionSamples(16);
  const double step = (r[1] - r[0]) / 15;
  s.Opacity->RemoveAllPoints();
  s.Opacity->AddPoint(r[0], 0.0);
  s.Opacity->AddPoint(r[0] + 7 * step, 0.0);
  s.Opacity->AddPoint(r[0] + 8 * step, 0.8);
  s.Opacity->AddPoint(r[1], 0.8);
  f.View.Window->Render();
  PSI_CHECK(mapper->GetLastUsedEarlyDiscard(), "coarse table: early discard compiled in");
  maxDiff = EarlyDiscardChange(f);
  mapper->SetTransferFunctionSamples(1024);
  PSI_CHECK(maxDiff == 0, "early discard changed the image, coarse table (max %d/255)", maxDiff);
  s.Opacity->DeepCopy(saved);
}
} // namespace

// Early ray termination. On a mesh of many draw chunks whose opacity turns a pixel opaque within
// a few cells, the frame composites front to back, the fragments behind opaque pixels fail the
// depth test before they are shaded: fewer samples pass than back to front, and the image is the
// same within 1/255. 'On' draws front to back even where no pixel turns opaque after all; under
// 'Auto' a mesh that can never turn a pixel opaque is drawn back to front, exactly as with the
// setting off (the timing of the ways is TestPsiMeasuredChoice's).
void CheckEarlyRayTermination(Fixture& f)
{
  vtkPsiVolumeMapper* mapper = f.Mapper;
  mapper->SetCountSamplesPassed(true);
  struct Frame
  {
    std::vector<double> Image;
    vtkIdType Samples;
    bool Used;
  };
  using ERT = psi::EarlyRayTerminations;
  auto draw = [&](ERT mode)
  {
    mapper->SetEarlyRayTermination(mode);
    std::vector<double> image = psitest::GrabRGB(f.View.Window);
    return Frame{ image, mapper->GetLastSamplesPassed(), mapper->GetLastUsedEarlyRayTermination() };
  };
  auto largest = [](const Frame& a, const Frame& b)
  { return psitest::LargestDifference(a.Image, b.Image); };
  Scene dense, faint;
  MakeScene(dense, 16, 0.375, 0.05); // opacity up to 0.9 per 0.05 units
  f.Draw(&dense);
  const Frame back = draw(ERT::Off), front = draw(ERT::On);
  std::printf("early ray termination, dense: %lld samples passed back to front, %lld front to "
              "back (%.0f%%), images %.0f/255 apart\n",
    static_cast<long long>(back.Samples), static_cast<long long>(front.Samples),
    100.0 * front.Samples / std::max<vtkIdType>(back.Samples, 1), 255 * largest(back, front));
  PSI_CHECK(!back.Used && front.Used, "dense: early ray termination used only when on");
  PSI_CHECK(back.Samples > 0 && front.Samples < back.Samples / 2,
    "dense: %lld samples passed front to back, %lld back to front",
    static_cast<long long>(front.Samples), static_cast<long long>(back.Samples));
  PSI_CHECK(largest(back, front) <= 1.0 / 255 + 1e-9, "dense: front to back %g/255 off",
    255 * largest(back, front));
  // A spike of opacity at the top of the range: by the bound a ray could turn opaque, but none
  // does. 'On' draws it front to back all the same, and 'Auto' starts front to back.
  Scene spike;
  MakeScene(spike, 16, 0.375, 1.0);
  double r[2];
  spike.Grid->GetPointData()->GetScalars()->GetRange(r);
  spike.Opacity->RemoveAllPoints();
  spike.Opacity->AddPoint(r[0], 0.0);
  spike.Opacity->AddPoint(r[1] - 0.01 * (r[1] - r[0]), 0.0);
  spike.Opacity->AddPoint(r[1], 1.0);
  f.Draw(&spike);
  const Frame forced = draw(ERT::On), spikeBack = draw(ERT::Off), first = draw(ERT::Auto);
  PSI_CHECK(
    forced.Used && !spikeBack.Used && first.Used && largest(forced, spikeBack) <= 1.0 / 255 + 1e-9,
    "spike: 'On' front to back %d, 'Off' %d, 'Auto' first %d (images %g/255 apart)", forced.Used,
    spikeBack.Used, first.Used, 255 * largest(forced, spikeBack));
  MakeScene(faint, 16, 0.375, 100.0); // at most 1 - exp(-0.009 * 20.8) = 0.17 along any ray
  f.Draw(&faint);
  const Frame off = draw(ERT::Off), on = draw(ERT::Auto);
  PSI_CHECK(!on.Used && on.Samples == off.Samples && largest(off, on) == 0,
    "faint: drawn front to back (%d), %lld samples against %lld, images %g/255 apart", on.Used,
    static_cast<long long>(on.Samples), static_cast<long long>(off.Samples),
    255 * largest(off, on));
  mapper->SetCountSamplesPassed(false);
  f.Draw(nullptr);
}

int main(int argc, char* argv[])
{
  Fixture f(psitest::ParseArguments(argc, argv));
  CheckPerspectiveMethods(f);
  CheckKuhnCellsOrder(f);
  CheckTimeStep(f);
  CheckFiveChunks(f);
  CheckParallel(f);
  CheckCameraInside(f);
  CheckCameraInsideParallel(f);
  CheckCameraInsideOpaque(f);
  CheckOpaquePlane(f);
  CheckCoarseCells(f);
  CheckEarlyDiscard(f);
  CheckEarlyRayTermination(f);

  vtkPsiVolumeMapper* mapper = f.Mapper;
  psitest::CheckRequestedProjector(mapper->GetLastUsedProjector());
  std::printf(
    "projector: %s\n", mapper->GetLastUsedProjector() ? "compute shader" : "geometry shader");
  return psitest::Report("TestPsiVolumeRender");
}
