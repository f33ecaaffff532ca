// The exact reference of several media (PsiReferenceMedia, psi::IntegrateReferenceMedia), checked
// against what it must reduce to, without OpenGL:
//  - one medium's segment is IntegrateReference's; a medium split into two of the same
//    luminance (tau = tau_1 + tau_2) is the whole; a medium with tau = 0 adds nothing; two
//    constant media have the closed form (tau_1 L_1 + tau_2 L_2) / tau (1 - exp(-tau D));
//  - one medium's image is RenderReference's, with a translucent surface and opaque geometry;
//    a mesh split into two media (disjoint, sharing an interface) is the whole mesh's image;
//    the same medium twice is the medium with its attenuation doubled; the media's order does
//    not matter.
#include "PsiReferenceIntegrals.h"
#include "PsiReferenceMedia.h"
#include "PsiTestCheck.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
double Largest(const psi::Rgba& a, const psi::Rgba& b)
{
  double worst = 0;
  for (int k = 0; k < 4; ++k)
  {
    worst = std::max(worst, std::abs(a[k] - b[k]));
  }
  return worst;
}

double Largest(const std::vector<double>& a, const std::vector<double>& b)
{
  double worst = a.size() == b.size() ? 0 : 1e300;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    worst = std::max(worst, std::abs(a[i] - b[i]));
  }
  return worst;
}

psi::Segment RandomSegment(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(0, 1);
  psi::Segment s;
  for (int k = 0; k < 3; ++k)
  {
    s.Lf[k] = u(rng);
    s.Lb[k] = u(rng);
  }
  s.tauf = 3 * u(rng);
  s.taub = 3 * u(rng);
  s.D = 0.05 + 2 * u(rng);
  return s;
}

void TestSegments()
{
  std::mt19937 rng(7);
  double alone = 0, split = 0, empty = 0, constant = 0;
  for (int n = 0; n < 200; ++n)
  {
    const psi::Segment s = RandomSegment(rng);
    const psi::Rgba exact = psi::IntegrateReference(s);
    alone = std::max(alone, Largest(psi::IntegrateReferenceMedia({ s }), exact));
    psi::Segment a = s, b = s; // the same luminance, the attenuation shared 30 : 70
    a.tauf *= 0.3;
    a.taub *= 0.3;
    b.tauf *= 0.7;
    b.taub *= 0.7;
    split = std::max(split, Largest(psi::IntegrateReferenceMedia({ a, b }), exact));
    psi::Segment none = RandomSegment(rng);
    none.tauf = none.taub = 0;
    none.D = s.D;
    empty = std::max(empty, Largest(psi::IntegrateReferenceMedia({ none, s }), exact));
    // two constant media: L = (tau1 L1 + tau2 L2) / tau, alpha = 1 - exp(-tau D)
    psi::Segment c1 = RandomSegment(rng), c2 = RandomSegment(rng);
    c1.Lb = c1.Lf;
    c2.Lb = c2.Lf;
    c1.taub = c1.tauf;
    c2.taub = c2.tauf;
    c2.D = c1.D;
    const double tau = c1.tauf + c2.tauf, alpha = -std::expm1(-tau * c1.D);
    psi::Rgba closed{ { 0, 0, 0, alpha } };
    for (int k = 0; k < 3; ++k)
    {
      closed[k] = (c1.tauf * c1.Lf[k] + c2.tauf * c2.Lf[k]) / tau * alpha;
    }
    constant = std::max(constant, Largest(psi::IntegrateReferenceMedia({ c1, c2 }), closed));
  }
  std::printf("segments: one medium %.2e, split %.2e, with an empty one %.2e, two constant "
              "%.2e\n",
    alone, split, empty, constant);
  PSI_CHECK(alone < 1e-12 && split < 1e-12 && empty < 1e-12 && constant < 1e-12,
    "the media's segment reduces to the exact ones (one medium %g, split %g, with an empty one "
    "%g, two constant %g)",
    alone, split, empty, constant);
}

// A camera looking at the Wavelet meshes' centre from (x, y, z), w x h pixels.
psi::ReferenceCamera CameraAt(double x, double y, double z, int w, int h)
{
  vtkNew<vtkCamera> cam;
  cam->SetPosition(x, y, z);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(30);
  cam->SetClippingRange(5, 80);
  vtkNew<vtkMatrix4x4> m;
  m->DeepCopy(cam->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1));
  m->Invert();
  psi::ReferenceCamera c;
  c.Width = w;
  c.Height = h;
  std::copy(m->GetData(), m->GetData() + 16, c.NdcToWorld.begin());
  c.Background = { { 0.1, 0.1, 0.15 } };
  return c;
}

// The tetrahedra of `scene` whose centroid lies on one side of the plane x + 0.4 y = 0.3.
psi::ReferenceScene Side(const psi::ReferenceScene& scene, bool below)
{
  psi::ReferenceScene half = scene;
  half.Tets.clear();
  for (const auto& t : scene.Tets)
  {
    double side = 0;
    for (int v : t)
    {
      side += 0.25 * (scene.Points[v][0] + 0.4 * scene.Points[v][1]);
    }
    if ((side < 0.3) == below)
    {
      half.Tets.push_back(t);
    }
  }
  return half;
}

void TestImages()
{
  vtkNew<vtkUnstructuredGrid> grid;
  psitest::MakeWaveletTets(grid, 4, 1.0);
  psitest::TransferFunction tf(2.0), other(1.0);
  psitest::BlueWhiteRed(tf.Color, 40, 280);
  psitest::LinearOpacity(tf.Opacity, 40, 280, 0.05, 0.7);
  psitest::BlueToYellow(other.Color, 40, 280);
  psitest::LinearOpacity(other.Opacity, 40, 280, 0.6, 0.1);
  psi::ReferenceScene scene = psitest::MakeReferenceScene(grid, tf);
  psi::ReferenceScene second = psitest::MakeReferenceScene(grid, other);
  psi::ReferenceSurface surface;
  surface.Triangles.push_back({ { { { -6, -6, -1 } }, { { 6, -6, 1 } }, { { -6, 7, 0.5 } } } });
  scene.Surfaces.push_back(surface);
  psi::ReferenceCamera cam = CameraAt(9, 12, 30, 48, 48);
  cam.OpaqueDepth.assign(48 * 48, 1.0f);
  cam.OpaqueColor.assign(3 * 48 * 48, 0.5f);
  for (int i = 0; i < 24 * 48; ++i) // an opaque wall in the lower half, inside the mesh
  {
    cam.OpaqueDepth[i] = 0.89f; // about 30 from the camera: the centre
  }
  const std::vector<double> one = psi::RenderReference(scene, cam);
  const double alone = Largest(psi::RenderReferenceMedia({ &scene }, cam), one);
  const psi::ReferenceScene lower = Side(scene, true), upper = Side(scene, false);
  psi::ReferenceScene upperBare = upper;
  upperBare.Surfaces.clear(); // the surface once, in the lower half's medium
  const double split = Largest(psi::RenderReferenceMedia({ &lower, &upperBare }, cam), one);
  // the same medium twice: twice its attenuation, the same luminance
  psi::ReferenceScene bare = scene, doubled = scene;
  bare.Surfaces.clear();
  const auto transfer = scene.Transfer;
  doubled.Transfer = [transfer](double v, double out[4])
  {
    transfer(v, out);
    out[3] *= 2;
  };
  const double twice =
    Largest(psi::RenderReferenceMedia({ &scene, &bare }, cam), psi::RenderReference(doubled, cam));
  const double order = Largest(psi::RenderReferenceMedia({ &scene, &second }, cam),
    psi::RenderReferenceMedia({ &second, &scene }, cam));
  const double differs = Largest(psi::RenderReferenceMedia({ &scene, &second }, cam), one);
  std::printf("images: one medium %.2e, split at an interface %.2e, the same medium twice %.2e, "
              "the order %.2e (a second medium changes it by %.3f; %zu + %zu tets)\n",
    alone, split, twice, order, differs, lower.Tets.size(), upper.Tets.size());
  PSI_CHECK(alone < 1e-9 && split < 1e-9 && twice < 1e-9 && order < 1e-12 && differs > 0.1 &&
      !lower.Tets.empty() && !upper.Tets.empty(),
    "the media's image reduces to the exact ones (one medium %g, split %g, twice %g, the order %g, "
    "a second medium changes it by %g)",
    alone, split, twice, order, differs);
}
} // namespace

int main()
{
  TestSegments();
  TestImages();
  return psitest::Report("TestReferenceMedia");
}
