// Isosurfaces and adaptive transfer-function sampling of vtkPsiVolumeMapper:
//  - every program variant (integration method x isosurfaces x adaptive sampling x projection,
//    near-plane and opaque clipping) compiles and renders; with no isovalue inside the data and a
//    linear transfer function each variant draws exactly the plain volume's image;
//  - a narrow opacity spike between vertex values is caught with adaptive sampling and missed
//    without it, measured against the exact CPU reference (PsiReferenceRaycaster, which splits
//    segments at transfer-function breakpoints); Auto turns it on for this transfer function only;
//  - an opaque isosurface hides the volume behind it, a translucent one does not;
//  - several isovalues and an isovalue exactly at a vertex value give no NaN;
//  - a new time step on the same mesh shades smooth isosurfaces with the new step's gradients.
// Needs an X server (run under xvfb-run). Usage: TestPsiIsosurfaces [output-dir]
#include "PsiIntegrationMethods.h"
#include "PsiReferenceRaycaster.h"
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
constexpr int W = 96, H = 96;

std::vector<double> Grab(vtkRenderWindow* win)
{
  return psitest::GrabRGB(win);
}

std::vector<double> Reference(vtkRenderer* ren, const psi::ReferenceScene& scene)
{
  return psi::RenderReference(scene, psitest::ReferenceCameraOf(ren, W, H));
}

bool Finite(const std::vector<double>& img)
{
  return std::all_of(img.begin(), img.end(), [](double v) { return std::isfinite(v); });
}

// What every check draws: the coarse Wavelet (scalar ranges per cell are wide) with a linear
// transfer function, seen by the mapper's view, and an opaque plane through it.
struct Scene
{
  std::string OutDir;
  vtkNew<vtkUnstructuredGrid> Grid;
  double R[2];
  double Span;
  psitest::TransferFunction TF{ 2.0 };
  vtkNew<vtkPsiVolumeMapper> Mapper;
  psitest::VolumeView View{ W, H, Mapper, TF.Property };
  vtkSmartPointer<vtkActor> Plane = psitest::MakeOpaquePlane(12);

  explicit Scene(const std::string& outDir)
    : OutDir(outDir)
  {
    psitest::ApplyRequested(this->Mapper.GetPointer());
    psitest::MakeWaveletTets(this->Grid, 3, 3.0);
    this->Grid->GetPointData()->GetScalars()->GetRange(this->R);
    this->Span = this->R[1] - this->R[0];
    psitest::BlueToYellow(this->TF.Color, this->R[0], this->R[1]);
    psitest::LinearOpacity(this->TF.Opacity, this->R[0], this->R[1], 0.02, 0.6);
    this->Mapper->SetInputData(this->Grid);
  }
};

void Outside(Scene& s)
{
  psitest::LookAtCentre(s.View.Renderer, 25, 17, 35);
}

// view 0: perspective, 1: parallel, 2: camera inside, 3: perspective with the opaque plane
// (which the caller removes)
void SetView(Scene& s, int view)
{
  vtkRenderer* ren = s.View.Renderer;
  Outside(s);
  if (view == 1)
  {
    ren->GetActiveCamera()->SetParallelProjection(1);
    ren->ResetCamera();
  }
  if (view == 2)
  {
    psitest::SetCameraInside(ren->GetActiveCamera());
  }
  if (view == 3)
  {
    ren->AddActor(s.Plane);
    ren->ResetCameraClippingRange();
  }
}

// 1. Every variant compiles and renders; features with nothing to do change nothing.
void CheckVariantsDrawThePlainVolume(Scene& s)
{
  vtkPsiVolumeMapper* mapper = s.Mapper;
  vtkRenderWindow* win = s.View.Window;
  const double* r = s.R;
  const std::vector<double> outOfRange1 = { r[1] + 10 };
  const std::vector<double> outOfRange3 = { r[0] - 30, r[1] + 10, r[1] + 20 };
  int variants = 0;
  for (int view = 0; view < 4; ++view) // perspective, parallel, camera inside, opaque plane
  {
    if (!psitest::RunsPart("view" + std::to_string(view)))
    {
      continue;
    }
    SetView(s, view);
    for (int method = 0; method < psi::NumberOfIntegrationMethods(); ++method)
    {
      mapper->SetIntegrationMethod(method);
      mapper->SetIsosurfaceValues({});
      mapper->SetAdaptiveSampling(psi::AdaptiveModes::Off);
      const std::vector<double> plain = Grab(win);
      const std::string plainDefines = mapper->GetLastFeatureDefines();
      for (int iso = 0; iso < 3; ++iso)
      {
        for (int adaptive = 0; adaptive < 2; ++adaptive)
        {
          if (iso == 0 && adaptive == 0)
          {
            continue;
          }
          mapper->SetIsosurfaceValues(iso == 0 ? std::vector<double>()
              : iso == 1                       ? outOfRange1
                                               : outOfRange3);
          mapper->SetAdaptiveSampling(adaptive ? psi::AdaptiveModes::On : psi::AdaptiveModes::Off);
          const std::vector<double> img = Grab(win);
          const std::string defs = mapper->GetLastFeatureDefines();
          const psitest::Difference d = psitest::DifferenceFrom(img, plain);
          ++variants;
          const bool hasIso =
            defs.find(iso == 1 ? "PSI_ISO_COUNT 1\n" : "PSI_ISO_COUNT 3\n") != std::string::npos;
          PSI_CHECK((iso == 0) == (defs.find("PSI_ISO_COUNT") == std::string::npos) &&
              (iso == 0 || hasIso) &&
              (adaptive == 1) == (defs.find("PSI_ADAPTIVE") != std::string::npos),
            "view %d method %d iso %d adaptive %d: defines\n%s", view, method, iso, adaptive,
            defs.c_str());
          PSI_CHECK(d.Max <= 1.5 / 255 && Finite(img),
            "view %d method %d iso %d adaptive %d: differs from the plain volume (max %g)", view,
            method, iso, adaptive, d.Max);
        }
      }
      mapper->SetIsosurfaceValues({});
      mapper->SetAdaptiveSampling(psi::AdaptiveModes::Off);
      Grab(win);
      PSI_CHECK(mapper->GetLastFeatureDefines() == plainDefines,
        "features switched off again give the plain program");
    }
    PSI_CHECK((view == 2) == mapper->GetLastUsedNearPlaneClipping(), "view %d near clip", view);
    PSI_CHECK((view == 3) == mapper->GetLastUsedOpaqueClipping(), "view %d opaque clip", view);
    s.View.Renderer->RemoveActor(s.Plane);
  }
  std::printf(
    "%d program variants rendered the plain image where they had nothing to add\n", variants);
  mapper->SetIntegrationMethod(static_cast<int>(psi::Method::PartialPreIntegration));
  Outside(s);
}

// 2. Adaptive sampling: a narrow opacity spike between vertex values.
void CheckAdaptiveSamplingCatchesASpike(Scene& s)
{
  vtkPsiVolumeMapper* mapper = s.Mapper;
  vtkRenderWindow* win = s.View.Window;
  vtkRenderer* ren = s.View.Renderer;
  vtkVolumeProperty* property = s.TF.Property;
  const double* r = s.R;
  const double span = s.Span;
  vtkNew<vtkPiecewiseFunction> spike;
  const double x0 = r[0] + 0.62 * span, w = 0.012 * span;
  spike->AddPoint(r[0], 0.0);
  spike->AddPoint(x0 - w, 0.0);
  spike->AddPoint(x0, 1.0);
  spike->AddPoint(x0 + w, 0.0);
  spike->AddPoint(r[1], 0.0);
  property->SetScalarOpacity(spike);
  property->SetScalarOpacityUnitDistance(1.0);
  const psi::ReferenceScene scene = psitest::MakeReferenceScene(s.Grid, s.TF.Color, spike, 1.0);
  const std::vector<double> ref = Reference(ren, scene);
  mapper->SetAdaptiveSampling(psi::AdaptiveModes::Off);
  const std::vector<double> off = Grab(win);
  mapper->SetAdaptiveSampling(psi::AdaptiveModes::On);
  const std::vector<double> on = Grab(win);
  // the spike's three control points and the range ends
  PSI_CHECK(mapper->GetLastNumberOfAdaptiveNodes() == 5, "spike nodes %d",
    mapper->GetLastNumberOfAdaptiveNodes());
  mapper->SetAdaptiveSampling(psi::AdaptiveModes::Auto);
  const std::vector<double> autoImg = Grab(win);
  PSI_CHECK(mapper->GetLastUsedAdaptiveSampling(), "Auto: the table misses the spike's peak");
  const psitest::Difference dOff = psitest::DifferenceFrom(off, ref),
                            dOn = psitest::DifferenceFrom(on, ref),
                            dAuto = psitest::DifferenceFrom(autoImg, on);
  // how much of the reference's spike (its difference from the background) each one shows
  const double* bg = ren->GetBackground();
  double sRef = 0, sOff = 0, sOn = 0;
  for (size_t i = 0; i < ref.size(); ++i)
  {
    sRef += std::abs(std::min(1.0, ref[i]) - bg[i % 3]);
    sOff += std::abs(off[i] - bg[i % 3]);
    sOn += std::abs(on[i] - bg[i % 3]);
  }
  std::printf("spike: error without adaptive sampling mean %.5f max %.4f (shows %.1f%% of it), "
              "with mean %.5f max %.4f (shows %.1f%%)\n",
    dOff.Mean, dOff.Max, 100 * sOff / sRef, dOn.Mean, dOn.Max, 100 * sOn / sRef);
  PSI_CHECK(dOn.Mean < 0.004 && dOn.Max < 0.08, "adaptive sampling catches the spike: %g / %g",
    dOn.Mean, dOn.Max);
  PSI_CHECK(dOff.Mean > 4 * dOn.Mean, "without adaptive sampling the spike is missed: %g vs %g",
    dOff.Mean, dOn.Mean);
  PSI_CHECK(std::abs(sOn / sRef - 1) < 0.05 && sOff < 0.9 * sRef,
    "spike energy: on %g off %g ref %g", sOn, sOff, sRef);
  PSI_CHECK(dAuto.Max <= 1.5 / 255, "Auto draws what On draws (%g)", dAuto.Max);
  if (!s.OutDir.empty())
  {
    psitest::WritePng(s.OutDir + "/spike_ref.png", ref, W, H);
    psitest::WritePng(s.OutDir + "/spike_adaptive_off.png", off, W, H);
    psitest::WritePng(s.OutDir + "/spike_adaptive_on.png", on, W, H);
  }
  property->SetScalarOpacity(s.TF.Opacity);
  property->SetScalarOpacityUnitDistance(2.0);
  Grab(win);
  PSI_CHECK(!mapper->GetLastUsedAdaptiveSampling(), "Auto: a linear function needs no splitting");
  mapper->SetAdaptiveSampling(psi::AdaptiveModes::Off);
}

// 3. Occlusion: the wavelet peaks at the center, so scalars above the isovalue lie inside the
// isosurface. The volume is visible (bright green) only there; an opaque isosurface hides it, a
// translucent one lets it through.
void CheckIsosurfaceOcclusion(Scene& s)
{
  vtkPsiVolumeMapper* mapper = s.Mapper;
  vtkRenderWindow* win = s.View.Window;
  vtkVolumeProperty* property = s.TF.Property;
  const double* r = s.R;
  const double span = s.Span;
  const double iso = r[0] + 0.75 * span; // a closed surface: not cut by the mesh boundary
  vtkNew<vtkColorTransferFunction> green;
  green->SetColorSpaceToRGB();
  green->AddRGBPoint(r[0], 0.0, 1.0, 0.0);
  green->AddRGBPoint(r[1], 0.0, 1.0, 0.0);
  vtkNew<vtkPiecewiseFunction> insideOnly;
  insideOnly->AddPoint(r[0], 0.0);
  // zero up to a few table samples beyond the isovalue: the sampled table is exactly zero on the
  // near side of the surface
  insideOnly->AddPoint(iso + 0.005 * span, 0.0);
  insideOnly->AddPoint(iso + 0.02 * span, 1.0);
  insideOnly->AddPoint(r[1], 1.0);
  property->SetColor(green);
  property->SetScalarOpacity(insideOnly);
  s.View.Renderer->SetBackground(0, 0, 0);
  const std::vector<double> volumeOnly = Grab(win);
  mapper->SetIsosurfaceValues({ iso });
  mapper->IsosurfaceUseColorMapOff();
  mapper->SetIsosurfaceColor(1, 0, 0);
  mapper->SetIsosurfaceShading(psi::IsosurfaceShadings::Unlit);
  mapper->SetIsosurfaceOpacity(1.0);
  const std::vector<double> opaque = Grab(win);
  mapper->SetIsosurfaceOpacity(0.5);
  const std::vector<double> half = Grab(win);
  double gVol = 0, gOpaque = 0, gHalf = 0, rOpaque = 0;
  int red = 0;
  for (int i = 0; i < W * H; ++i)
  {
    gVol += volumeOnly[3 * i + 1];
    gOpaque += opaque[3 * i + 1];
    gHalf += half[3 * i + 1];
    rOpaque += opaque[3 * i];
    red += opaque[3 * i] > 0.9;
  }
  std::printf("occlusion: green volume alone %.1f, behind an opaque isosurface %.1f, behind a "
              "translucent one %.1f; red pixels %d\n",
    gVol, gOpaque, gHalf, red);
  PSI_CHECK(gVol > 50 && red > W * H / 10, "scene not empty (%g, %d)", gVol, red);
  PSI_CHECK(gOpaque < 1e-2 * gVol, "an opaque isosurface hides the volume behind it (%g)", gOpaque);
  PSI_CHECK(
    gHalf > 0.3 * gVol && gHalf < 0.7 * gVol, "a translucent one lets half through (%g)", gHalf);
  if (!s.OutDir.empty())
  {
    psitest::WritePng(s.OutDir + "/occlusion_volume.png", volumeOnly, W, H);
    psitest::WritePng(s.OutDir + "/occlusion_opaque.png", opaque, W, H);
    psitest::WritePng(s.OutDir + "/occlusion_half.png", half, W, H);
  }
  property->SetColor(s.TF.Color);
  property->SetScalarOpacity(s.TF.Opacity);
  mapper->SetIsosurfaceShading(psi::IsosurfaceShadings::Smooth);
  mapper->IsosurfaceUseColorMapOn();
  mapper->SetIsosurfaceOpacity(1.0);
}

// 4. Several isovalues in one cell, and an isovalue exactly at a vertex value.
void CheckIsovaluesAtAVertex(Scene& s)
{
  vtkPsiVolumeMapper* mapper = s.Mapper;
  const double span = s.Span;
  vtkDataArray* sc = s.Grid->GetPointData()->GetScalars();
  const double v = sc->GetComponent(sc->GetNumberOfTuples() / 2 + 3, 0);
  for (const std::vector<double>& values :
    { std::vector<double>{ v },
      std::vector<double>{ v - 0.02 * span, v, v + 0.01 * span, v + 0.03 * span, v + 0.2 * span } })
  {
    mapper->SetIsosurfaceValues(values);
    for (int view = 0; view < 3; ++view)
    {
      SetView(s, view);
      const std::vector<double> img = Grab(s.View.Window);
      int lit = 0;
      for (int i = 0; i < W * H; ++i)
      {
        lit += img[3 * i] + img[3 * i + 1] + img[3 * i + 2] > 0.3;
      }
      PSI_CHECK(Finite(img) && lit > W * H / 20, "%zu isovalues at a vertex value, view %d: %d",
        values.size(), view, lit);
      if (!s.OutDir.empty())
      {
        psitest::WritePng(s.OutDir + "/iso" + std::to_string(values.size()) + "_view" +
            std::to_string(view) + ".png",
          img, W, H);
      }
    }
  }
}

// An isosurface case of CheckIsosurfaceMethodsAgree.
struct IsoCase
{
  const char* Name;
  std::vector<double> Values;
  double Opacity;
  psi::IsosurfaceShadings Shading;
  bool Gap;
  bool FitsGS; // marching tetrahedra fit the geometry shader's output in every view
  std::vector<double> Opacities; // each surface's own (IsosurfaceOpacities)
};

// Case `k` (number `index`) in view `view` (SetView) with each isosurface method, and Auto.
void CheckIsosurfaceMethodsAgreeInView(Scene& s, const IsoCase& k, int index, int view)
{
  vtkPsiVolumeMapper* mapper = s.Mapper;
  vtkRenderWindow* win = s.View.Window;
  SetView(s, view);
  mapper->SetIsosurfaceMethod(psi::IsosurfaceMethods::PerFragment);
  const std::vector<double> perFragment = Grab(win);
  PSI_CHECK(
    mapper->GetLastUsedIsosurfaceMethod() == static_cast<int>(psi::IsosurfaceMethods::PerFragment),
    "per-fragment method used");
  mapper->SetIsosurfaceMethod(psi::IsosurfaceMethods::MarchingTetrahedra);
  const std::vector<double> mt = Grab(win);
  const bool usedMT = mapper->GetLastUsedIsosurfaceMethod() ==
    static_cast<int>(psi::IsosurfaceMethods::MarchingTetrahedra);
  const bool discarded = mapper->GetLastUsedEarlyDiscard();
  // front to back (early ray termination, chosen where a surface can hide what is behind it)
  // each cell's pieces and surfaces are emitted in the reverse sequence: the same image as back
  // to front within 1/255
  const bool frontToBack = mapper->GetLastUsedEarlyRayTermination();
  double fromBack = 0;
  if (frontToBack && usedMT)
  {
    const int own = mapper->GetEarlyRayTermination();
    mapper->SetEarlyRayTermination(psi::EarlyRayTerminations::Off);
    fromBack = psitest::DifferenceFrom(mt, Grab(win)).Max;
    mapper->SetEarlyRayTermination(own);
  }
  PSI_CHECK(fromBack <= 1.0 / 255 + 1e-9,
    "%s view %d: drawn front to back (%d), %g/255 from back to front", k.Name, view, frontToBack,
    255 * fromBack);
  mapper->SetIsosurfaceMethod(psi::IsosurfaceMethods::Auto);
  Grab(win);
  PSI_CHECK(mapper->GetLastUsedIsosurfaceMethod() ==
      static_cast<int>(k.Gap && k.FitsGS ? psi::IsosurfaceMethods::MarchingTetrahedra
                                         : psi::IsosurfaceMethods::PerFragment),
    "%s view %d: Auto uses marching tetrahedra exactly when early discard applies", k.Name, view);
  s.View.Renderer->RemoveActor(s.Plane);
  const psitest::Difference d = psitest::DifferenceFrom(mt, perFragment);
  int differ = 0;
  for (size_t i = 0; i < mt.size(); i += 3)
  {
    differ += std::abs(mt[i] - perFragment[i]) + std::abs(mt[i + 1] - perFragment[i + 1]) +
        std::abs(mt[i + 2] - perFragment[i + 2]) >
      6.0 / 255;
  }
  std::printf("isosurfaces %-18s view %d: marching tetrahedra%s vs per fragment: mean %.5f "
              "max %.3f, %.2f%% of pixels differ by > 2/255 a channel; vs back to front %.0f/255\n",
    k.Name, view, usedMT ? (discarded ? " (early discard)" : "") : " (not used: limit)", d.Mean,
    d.Max, 100.0 * differ / (W * H), frontToBack ? 255 * fromBack : -1.0);
  PSI_CHECK(usedMT == k.FitsGS,
    "%s view %d: marching tetrahedra used where they fit the geometry shader's output, "
    "per fragment beyond",
    k.Name, view);
  PSI_CHECK(
    discarded == (k.Gap && usedMT), "%s view %d: early discard with isosurfaces", k.Name, view);
  PSI_CHECK(Finite(mt) && d.Mean < 5e-4 && differ < W * H / 100,
    "%s view %d: the methods agree (mean %g, %d pixels differ)", k.Name, view, d.Mean, differ);
  if (!s.OutDir.empty())
  {
    const std::string base =
      s.OutDir + "/methods_" + std::to_string(index) + "_view" + std::to_string(view);
    psitest::WritePng(base + "_mt.png", mt, W, H);
    psitest::WritePng(base + "_fragment.png", perFragment, W, H);
  }
}

// 5. The two isosurface methods (marching tetrahedra in the geometry shader, per-fragment
// crossings) are independent implementations of the same image: they agree in every view, with
// translucent surfaces in a visible volume, several isovalues, flat and smooth shading, and early
// discard of the zero-opacity pieces (marching tetrahedra only).
void CheckIsosurfaceMethodsAgree(Scene& s)
{
  vtkPsiVolumeMapper* mapper = s.Mapper;
  const double* r = s.R;
  const double span = s.Span;
  const double a = r[0] + 0.55 * span, b = r[0] + 0.7 * span, c = r[0] + 0.8 * span;
  vtkNew<vtkPiecewiseFunction> gap; // zero opacity on the lower half: early discard
  gap->AddPoint(r[0], 0.0);
  gap->AddPoint(r[0] + 0.5 * span, 0.0);
  gap->AddPoint(r[0] + 0.6 * span, 0.6);
  gap->AddPoint(r[1], 0.8);
  std::vector<double> twelve;
  for (int i = 0; i < 12; ++i)
  {
    twelve.push_back(r[0] + (0.4 + 0.04 * i) * span);
  }
  const IsoCase cases[] = { { "one", { b }, 1.0, psi::IsosurfaceShadings::Smooth, false, true },
    { "three translucent", { a, b, c }, 0.4, psi::IsosurfaceShadings::Smooth, false, true },
    { "three flat", { c, a, b }, 0.6, psi::IsosurfaceShadings::Flat, false, true },
    { "two, opacity gap", { r[0] + 0.3 * span, b }, 0.5, psi::IsosurfaceShadings::Smooth, true,
      true },
    { "twelve (GS limit)", twelve, 0.3, psi::IsosurfaceShadings::Smooth, false, false },
    { "three own opacities", { a, b, c }, 1.0, psi::IsosurfaceShadings::Smooth, true, true,
      { 0.2, 1.0, 0.5 } } };
  for (const IsoCase& k : cases)
  {
    s.TF.Property->SetScalarOpacity(k.Gap ? gap.Get() : s.TF.Opacity.Get());
    mapper->SetIsosurfaceValues(k.Values);
    mapper->SetIsosurfaceOpacity(k.Opacity);
    mapper->SetIsosurfaceShading(k.Shading);
    mapper->SetIsosurfaceOpacities(k.Opacities);
    for (int view = 0; view < 4; ++view)
    {
      if (psitest::RunsPart("view" + std::to_string(view)))
      {
        CheckIsosurfaceMethodsAgreeInView(s, k, static_cast<int>(&k - cases), view);
      }
    }
  }
  s.TF.Property->SetScalarOpacity(s.TF.Opacity);
  mapper->SetIsosurfaceOpacities({});
  mapper->SetIsosurfaceShading(psi::IsosurfaceShadings::Smooth);
  mapper->SetIsosurfaceOpacity(1.0);
}

// `grid`'s next time step: the same points and cells, the scalars tilted by a term in x (the
// same array name, new values).
void MakeTiltedStep(vtkUnstructuredGrid* grid, double span, vtkUnstructuredGrid* step)
{
  step->ShallowCopy(grid);
  vtkNew<vtkDoubleArray> tilted;
  tilted->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    tilted->SetValue(
      i, grid->GetPointData()->GetScalars()->GetComponent(i, 0) + 0.08 * span * x[0]);
  }
  tilted->SetName(grid->GetPointData()->GetScalars()->GetName()); // the same array, a new step
  step->GetPointData()->SetScalars(tilted);
}

// 6. A new time step on the same mesh with smooth-shaded isosurfaces: the mesh is not gathered
// again, but its point gradients (the surfaces' normals) follow the new scalars. The step's image
// must be the image of a mapper that sees that step first. The new field tilts the old one's
// gradients (a term in x), so stale normals shade the surfaces differently.
void CheckTimeStepGradients(Scene& s)
{
  vtkPsiVolumeMapper* mapper = s.Mapper;
  vtkRenderWindow* win = s.View.Window;
  SetView(s, 0);
  const double iso = s.R[0] + 0.6 * s.Span;
  mapper->SetIsosurfaceValues({ iso });
  mapper->SetIsosurfaceShading(psi::IsosurfaceShadings::Smooth);
  for (psi::IsosurfaceMethods method :
    { psi::IsosurfaceMethods::MarchingTetrahedra, psi::IsosurfaceMethods::PerFragment })
  {
    mapper->SetIsosurfaceMethod(method);
    mapper->SetInputData(s.Grid);
    Grab(win); // the first step, its gradients on the GPU
    const int version = mapper->GetMeshVersion();
    vtkNew<vtkUnstructuredGrid> step;
    MakeTiltedStep(s.Grid, s.Span, step);
    mapper->SetInputData(step);
    const std::vector<double> next = Grab(win);
    const bool sameMesh = mapper->GetMeshVersion() == version;
    vtkNew<vtkUnstructuredGrid> copy; // new points and cells: gathered from scratch
    copy->DeepCopy(step);
    mapper->SetInputData(copy);
    const std::vector<double> fresh = Grab(win);
    const psitest::Difference d = psitest::DifferenceFrom(next, fresh);
    std::printf("time step, smooth isosurfaces (%s): vs the step drawn first: mean %.5f max "
                "%.3f\n",
      method == psi::IsosurfaceMethods::PerFragment ? "per fragment" : "marching tetrahedra",
      d.Mean, d.Max);
    PSI_CHECK(sameMesh && mapper->GetMeshVersion() != version,
      "time step: the same mesh took the new scalars, the copy was gathered anew");
    PSI_CHECK(d.Mean < 1e-4 && d.Max <= 1.5 / 255,
      "time step, smooth isosurfaces (method %d): "
      "the image of the step drawn first (mean %g, max %g)",
      static_cast<int>(method), d.Mean, d.Max);
  }
  mapper->SetInputData(s.Grid);
  mapper->SetIsosurfaceValues({});
  mapper->SetIsosurfaceMethod(psi::IsosurfaceMethods::Auto);
}
} // namespace

int main(int argc, char* argv[])
{
  // --part view0 ... view3: checks 1 and 5 in that view; --part others: checks 2, 3, 4 and 6
  // (CTest runs each part as a test of its own: each compiles about a fifth of the programs)
  Scene s(psitest::ParseArguments(argc, argv));
  CheckVariantsDrawThePlainVolume(s);
  if (psitest::RunsPart("others"))
  {
    CheckAdaptiveSamplingCatchesASpike(s);
    CheckIsosurfaceOcclusion(s);
    CheckIsovaluesAtAVertex(s);
  }
  CheckIsosurfaceMethodsAgree(s);
  if (psitest::RunsPart("others"))
  {
    CheckTimeStepGradients(s);
  }

  vtkPsiVolumeMapper* mapper = s.Mapper;
  psitest::CheckRequestedProjector(mapper->GetLastUsedProjector());
  std::printf(
    "projector: %s\n", mapper->GetLastUsedProjector() ? "compute shader" : "geometry shader");
  return psitest::Report("TestPsiIsosurfaces");
}
