// Translucent geometry intermixed with 'Psi Volume' through VTK's dual depth peeling (the
// renderer's UseDepthPeelingForVolumes, ParaView's DepthPeelingForVolumes), against the exact
// reference: the reference ray caster compositing the surfaces' layers at their depths
// (psi::ReferenceSurface, the same triangles GL draws). A translucent unlit sphere in front of
// the volume, behind it, cutting through it, and two nested spheres cutting through it; each with
// the geometry-shader and the compute projector (--projector), perspective and parallel.
// Spheres in front of and behind an opaque plane with the volume between. Without depth peeling
// for volumes VTK draws volumes after all translucent geometry, which
// cannot be intermixed: the mapper then warns once.
#include "PsiReferenceRaycaster.h"
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <string>
#include <vector>

namespace
{
constexpr int W = 96, H = 96;

struct Sphere
{
  double Center[3];
  double Radius;
  double Color[3];
  double Opacity; // low enough that the volume behind three layers still shows
};

// An unlit translucent sphere actor, and the same triangles for the reference.
vtkSmartPointer<vtkActor> MakeSphere(const Sphere& s, psi::ReferenceScene& ref)
{
  vtkNew<vtkSphereSource> source;
  source->SetCenter(s.Center[0], s.Center[1], s.Center[2]);
  source->SetRadius(s.Radius);
  source->SetThetaResolution(48);
  source->SetPhiResolution(48);
  source->Update();
  vtkPolyData* poly = source->GetOutput();
  psi::ReferenceSurface surface;
  surface.Color = { { s.Color[0], s.Color[1], s.Color[2] } };
  surface.Opacity = s.Opacity;
  vtkCellArray* polys = poly->GetPolys();
  polys->InitTraversal();
  vtkIdType n;
  const vtkIdType* ids;
  while (polys->GetNextCell(n, ids))
  {
    for (vtkIdType k = 1; k + 1 < n; ++k) // a fan (the sphere's cells are triangles)
    {
      std::array<std::array<double, 3>, 3> tri;
      poly->GetPoint(ids[0], tri[0].data());
      poly->GetPoint(ids[k], tri[1].data());
      poly->GetPoint(ids[k + 1], tri[2].data());
      surface.Triangles.push_back(tri);
    }
  }
  ref.Surfaces.push_back(surface);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(s.Color[0], s.Color[1], s.Color[2]);
  actor->GetProperty()->SetOpacity(surface.Opacity);
  return actor;
}
// The cases' spheres along the view direction: in front of the volume's bounding sphere, behind
// it, through it, and two nested ones through it.
struct Case
{
  const char* Name;
  std::vector<Sphere> Spheres;
};

std::vector<Case> Cases()
{
  const double toEye[3] = { 21 / 38.5, 14 / 38.5, 29 / 38.5 };
  auto along = [&](double t, double radius, const double rgb[3])
  {
    return Sphere{ { t * toEye[0], t * toEye[1], t * toEye[2] }, radius, { rgb[0], rgb[1], rgb[2] },
      0.5 };
  };
  const double orange[3] = { 1.0, 0.5, 0.25 };
  return {
    { "sphere_in_front", { along(16, 3, orange) } },
    { "sphere_behind", { along(-15, 4, orange) } },
    { "sphere_through", { Sphere{ { 2, 1, 3 }, 5, { 1.0, 0.5, 0.25 }, 0.5 } } },
    { "nested_spheres",
      { Sphere{ { -1, 0, 1 }, 3, { 0.2, 0.9, 0.3 }, 0.25 },
        Sphere{ { -1, 0, 1 }, 6.5, { 1.0, 0.5, 0.25 }, 0.25 } } },
  };
}

// The Wavelet on [-6, 6]^3 in a view that peels translucent geometry, volumes included.
struct Scene
{
  std::string OutDir;
  vtkNew<vtkUnstructuredGrid> Grid;
  psitest::TransferFunction TF{ 2.0 };
  vtkNew<vtkPsiVolumeMapper> Mapper;
  psitest::VolumeView View{ W, H, Mapper, TF.Property };

  explicit Scene(const std::string& outDir)
    : OutDir(outDir)
  {
    psitest::ApplyRequested(this->Mapper.GetPointer());
    psitest::MakeWaveletTets(this->Grid, 6, 1.0);
    double r[2];
    this->Grid->GetPointData()->GetScalars()->GetRange(r);
    psitest::BlueWhiteRed(this->TF.Color, r[0], r[1]);
    psitest::LinearOpacity(this->TF.Opacity, r[0], r[1], 0.05, 0.8);
    this->Mapper->SetInputData(this->Grid);
    vtkRenderer* ren = this->View.Renderer;
    this->View.Window->SetAlphaBitPlanes(1);
    ren->SetUseDepthPeeling(1);
    ren->SetUseDepthPeelingForVolumes(true);
    ren->SetMaximumNumberOfPeels(16);
    ren->SetOcclusionRatio(0.0);
    psitest::LookAtCentre(ren, 21, 14, 29);
  }

  // Adds the spheres to the renderer and to `ref`.
  std::vector<vtkSmartPointer<vtkActor>> AddSpheres(
    const std::vector<Sphere>& spheres, psi::ReferenceScene& ref)
  {
    std::vector<vtkSmartPointer<vtkActor>> actors;
    for (const Sphere& s : spheres)
    {
      actors.push_back(MakeSphere(s, ref));
      this->View.Renderer->AddActor(actors.back());
    }
    return actors;
  }

  void Remove(const std::vector<vtkSmartPointer<vtkActor>>& actors)
  {
    for (auto& a : actors)
    {
      this->View.Renderer->RemoveActor(a);
    }
  }
};

// Each case in perspective and in parallel projection, against the exact compositing.
void CheckSpheres(Scene& s, const std::vector<Case>& cases)
{
  vtkRenderer* ren = s.View.Renderer;
  vtkCamera* cam = ren->GetActiveCamera();
  for (const bool parallel : { false, true })
  {
    cam->SetParallelProjection(parallel);
    cam->SetParallelScale(9);
    ren->ResetCameraClippingRange(-20, 20, -20, 20, -20, 20);
    for (const Case& k : cases)
    {
      psi::ReferenceScene ref = psitest::MakeReferenceScene(s.Grid, s.TF);
      const std::vector<vtkSmartPointer<vtkActor>> actors = s.AddSpheres(k.Spheres, ref);
      const std::string name = std::string(k.Name) + (parallel ? "_parallel" : "");
      const psitest::Result res =
        psitest::Compare(name, s.View.Window, ren, s.View.Volume, ref, nullptr, s.OutDir);
      // A pixel whose ray grazes a triangle edge of the sphere may see the layer on one side
      // only: a few outlying channels are allowed, not a wrong order.
      PSI_CHECK(res.Mean < 0.004 && res.Outliers < 0.002 && res.P999 < 0.015,
        "%s: mean error %g, %g%% over 0.05, 99.9th percentile %g", name.c_str(), res.Mean,
        100 * res.Outliers, res.P999);
      PSI_CHECK(res.Covered > W * H / 8, "%s: image nearly empty", name.c_str());
      // The frame is all its depth-peeling stages: 'Auto' weighs the whole still frame against
      // its budget, not the last stage's call (psi::FrameClock).
      PSI_CHECK(s.Mapper->GetLastFrameCalls() > 1 &&
          s.Mapper->GetLastStillSeconds() == s.Mapper->GetLastRenderSeconds(),
        "%s: the still frame counted over its %d depth-peeling calls", name.c_str(),
        s.Mapper->GetLastFrameCalls());
      s.Remove(actors);
    }
  }
}

// Opaque geometry through the volume and a translucent sphere through both: the intervals end
// at the opaque surface (before the peels: behind the layers up to it; in a peel: the front
// interval clamped to it).
void CheckSphereAndOpaquePlane(Scene& s, const Sphere& sphereThrough)
{
  vtkRenderer* ren = s.View.Renderer;
  ren->GetActiveCamera()->SetParallelProjection(false);
  ren->ResetCameraClippingRange(-20, 20, -20, 20, -20, 20);
  psi::ReferenceScene ref = psitest::MakeReferenceScene(s.Grid, s.TF);
  vtkSmartPointer<vtkActor> sphere = MakeSphere(sphereThrough, ref);
  vtkSmartPointer<vtkActor> plane = psitest::MakeOpaquePlane(6.0);
  ren->AddActor(sphere);
  ren->AddActor(plane);
  const psitest::Result res = psitest::Compare(
    "sphere_and_opaque_plane", s.View.Window, ren, s.View.Volume, ref, plane, s.OutDir, { sphere });
  PSI_CHECK(res.Mean < 0.004 && res.Outliers < 0.002 && res.P999 < 0.015,
    "sphere and opaque plane: mean error %g, %g%% over 0.05, 99.9th percentile %g", res.Mean,
    100 * res.Outliers, res.P999);
  ren->RemoveActor(sphere);
  ren->RemoveActor(plane);
}

// Translucent geometry in front of and behind opaque geometry, the volume between: a sphere
// between the eye and the opaque plane inside the volume, another behind the plane (seen only
// around its edges). Each stage integrates the volume from the layers in front up to the plane
// and nothing behind it; the sphere behind shows only where the plane does not hide it.
void CheckSpheresAroundOpaquePlane(Scene& s)
{
  vtkRenderer* ren = s.View.Renderer;
  ren->GetActiveCamera()->SetParallelProjection(false);
  ren->ResetCameraClippingRange(-20, 20, -20, 20, -20, 20);
  psi::ReferenceScene ref = psitest::MakeReferenceScene(s.Grid, s.TF);
  const double toEye[3] = { 21 / 38.5, 14 / 38.5, 29 / 38.5 };
  const Sphere front{ { 3.5 * toEye[0], 3.5 * toEye[1], 3.5 * toEye[2] }, 2.0, { 1.0, 0.5, 0.25 },
    0.4 };
  const Sphere behind{ { -3.0 * toEye[0] + 5.0, -3.0 * toEye[1], -3.0 * toEye[2] }, 3.0,
    { 0.3, 0.4, 1.0 }, 0.4 };
  vtkSmartPointer<vtkActor> a = MakeSphere(front, ref);
  vtkSmartPointer<vtkActor> b = MakeSphere(behind, ref);
  vtkSmartPointer<vtkActor> plane = psitest::MakeOpaquePlane(4.0);
  for (vtkActor* actor : { a.Get(), b.Get(), plane.Get() })
  {
    ren->AddActor(actor);
  }
  const psitest::Result res = psitest::Compare("spheres_around_opaque_plane", s.View.Window, ren,
    s.View.Volume, ref, plane, s.OutDir, { a, b });
  PSI_CHECK(res.Mean < 0.004 && res.Outliers < 0.002 && res.P999 < 0.015,
    "spheres in front of and behind an opaque plane: mean error %g, %g%% over 0.05, 99.9th "
    "percentile %g",
    res.Mean, 100 * res.Outliers, res.P999);
  PSI_CHECK(res.Covered > W * H / 8, "spheres around an opaque plane: image nearly empty");
  for (vtkActor* actor : { a.Get(), b.Get(), plane.Get() })
  {
    ren->RemoveActor(actor);
  }
}

// Peeling stopped after one peel: the two inner layers and the volume between them are left to
// the pass's final alpha blend, which composites them in draw order (VTK's approximation), so
// the image differs from the exact one only inside the inner sphere, by about one layer. Then,
// without depth peeling for volumes, VTK draws the volume after all translucent geometry: the
// mapper says so, once.
void CheckOnePeelAndNoVolumePeeling(Scene& s, const std::vector<Sphere>& nested)
{
  vtkRenderer* ren = s.View.Renderer;
  ren->GetActiveCamera()->SetParallelProjection(false);
  ren->ResetCameraClippingRange(-20, 20, -20, 20, -20, 20);
  ren->SetMaximumNumberOfPeels(1);
  psi::ReferenceScene ref = psitest::MakeReferenceScene(s.Grid, s.TF);
  const std::vector<vtkSmartPointer<vtkActor>> actors = s.AddSpheres(nested, ref);
  const psitest::Result res =
    psitest::Compare("nested_one_peel", s.View.Window, ren, s.View.Volume, ref, nullptr, s.OutDir);
  PSI_CHECK(res.Mean < 0.02 && res.Covered > W * H / 8,
    "one peel, then the final blend: mean error %g", res.Mean);
  ren->SetMaximumNumberOfPeels(16);

  int warnings = 0;
  vtkNew<vtkCallbackCommand> onWarning;
  onWarning->SetClientData(&warnings);
  onWarning->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  s.Mapper->AddObserver(vtkCommand::WarningEvent, onWarning);
  ren->SetUseDepthPeelingForVolumes(false);
  s.View.Window->Render();
  s.View.Window->Render();
  PSI_CHECK(warnings == 1, "without depth peeling for volumes: %d warnings (1 expected)", warnings);
  s.Remove(actors);
  s.View.Window->Render();
  PSI_CHECK(warnings == 1, "no translucent geometry: no more warnings (%d)", warnings);
}
} // namespace

int main(int argc, char* argv[])
{
  Scene s(psitest::ParseArguments(argc, argv));
  const std::vector<Case> cases = Cases();
  CheckSpheres(s, cases);
  CheckSphereAndOpaquePlane(s, cases[2].Spheres[0]);
  CheckSpheresAroundOpaquePlane(s);
  CheckOnePeelAndNoVolumePeeling(s, cases[3].Spheres);
  return psitest::Report("TestPsiTranslucentGeometry");
}
