// Several volumes in one renderer, intermixed (PsiIntermixedFrames.h, Core/PsiIntermixedMesh.h):
//  - two Wavelets that do not share space but overlap on screen (the second placed by its
//    volume's matrix) give the image of their union drawn as one volume (vtkAppendFilter of the
//    two, the second moved by the same transform), in both orders of the renderer's volumes, from
//    three views (each volume in front in one of them): within 1/255;
//  - with different color maps, opacity functions and unit distances, the image does not depend
//    on the order of the volumes, and each volume keeps its own transfer function (each
//    differs from the scene drawn with the other's);
//  - an isosurface in each volume (a value outside one's range dropped) gives the union's image
//    with it; a mesh split into two volumes along a slanted plane draws as the whole mesh;
//  - the camera inside one of them, an opaque plane through both, a translucent plane through
//    both within dual depth peeling: the union's image;
//  - hiding one gives the other alone; each volume reads out its own tetrahedra.
// On one renderer's volumes drawn one after the other the later is pasted over the earlier:
// the orders differ by up to 70/255 there.
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkAppendFilter.h"
#include "vtkCamera.h"
#include "vtkExtractCells.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace
{
const int W = 160, H = 160;
const double Offset[3] = { 3, 2,
  12 }; // the second Wavelet's place: apart in z, overlapping in x, y

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> A, B;
  vtkNew<vtkPsiVolumeMapper> MapperA, MapperB;

  Scene(vtkUnstructuredGrid* grid, vtkVolumeProperty* pa, vtkVolumeProperty* pb, bool bFirst)
  {
    this->Window->SetSize(W, H);
    this->Window->SetMultiSamples(0);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->AddRenderer(this->Renderer);
    this->MapperA->SetInputData(grid);
    this->MapperB->SetInputData(grid);
    psitest::ApplyRequested(this->MapperA.GetPointer());
    psitest::ApplyRequested(this->MapperB.GetPointer());
    this->A->SetMapper(this->MapperA);
    this->B->SetMapper(this->MapperB);
    this->A->SetProperty(pa);
    this->B->SetProperty(pb);
    this->B->SetPosition(Offset[0], Offset[1], Offset[2]);
    this->Renderer->AddVolume(bFirst ? this->B : this->A);
    this->Renderer->AddVolume(bFirst ? this->A : this->B);
  }
};

// Camera `view` of three around the two Wavelets' middle: from +z (the second in front), from -z
// (the first in front), and from the side.
void SetView(vtkRenderer* ren, int view)
{
  const double c[3] = { 2, 1, 6 };
  const double dir[3][3] = { { 0.15, 0.1, 1 }, { -0.1, 0.2, -1 }, { 1, 0.4, 0.3 } };
  const double d = 48 /
    std::sqrt(
      dir[view][0] * dir[view][0] + dir[view][1] * dir[view][1] + dir[view][2] * dir[view][2]);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(c[0], c[1], c[2]);
  cam->SetPosition(c[0] + d * dir[view][0], c[1] + d * dir[view][1], c[2] + d * dir[view][2]);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(30);
  ren->ResetCameraClippingRange();
}

std::vector<double> Draw(vtkRenderWindow* win, vtkRenderer* ren, int view)
{
  SetView(ren, view);
  return psitest::GrabRGB(win);
}

double Mean(const std::vector<double>& a, const std::vector<double>& b)
{
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    sum += std::abs(a[i] - b[i]);
  }
  return a.empty() ? 0 : sum / a.size();
}

// The cells of `grid` whose centroid lies on one side of the plane 0.3 x + 0.2 y + z = 0.4
// (`below`) or the other: two meshes with an interface, each with its own points on it.
vtkSmartPointer<vtkUnstructuredGrid> Side(vtkUnstructuredGrid* grid, bool below)
{
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType n = 0;
    const vtkIdType* pts = nullptr;
    grid->GetCellPoints(c, n, pts);
    double side = 0;
    for (vtkIdType k = 0; k < n; ++k)
    {
      double x[3];
      grid->GetPoint(pts[k], x);
      side += 0.3 * x[0] + 0.2 * x[1] + x[2];
    }
    if ((side / n < 0.4) == below)
    {
      ids->InsertNextId(c);
    }
  }
  vtkNew<vtkExtractCells> extract;
  extract->SetInputData(grid);
  extract->SetCellList(ids);
  extract->Update();
  return extract->GetOutput();
}

// A translucent slanted plane through both Wavelets, and depth peeling with volumes on `ren`
// (VTK's dual depth peeling calls each volume once per stage of a frame).
void AddTranslucentPlane(vtkRenderWindow* win, vtkRenderer* ren)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-8, -6, -4);
  plane->SetPoint1(14, -6, 20);
  plane->SetPoint2(-8, 10, -4);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(0.2, 0.8, 0.3);
  actor->GetProperty()->SetOpacity(0.4);
  ren->AddActor(actor);
  win->SetAlphaBitPlanes(1);
  ren->SetUseDepthPeeling(1);
  ren->SetUseDepthPeelingForVolumes(true);
  ren->SetMaximumNumberOfPeels(16);
  ren->SetOcclusionRatio(0.0);
}

// Pixels that differ from the background: how much of the image a volume covers.
int Covered(const std::vector<double>& a)
{
  int n = 0;
  for (size_t i = 0; i + 2 < a.size(); i += 3)
  {
    n += std::abs(a[i] - 0.1) + std::abs(a[i + 1] - 0.1) + std::abs(a[i + 2] - 0.15) > 0.02;
  }
  return n;
}
} // namespace

// The scene every check shares: the Wavelet, the union of it and its moved copy drawn as one
// volume (`One`), and the two volumes in both orders of the renderer (`AB`, `BA`).
struct Fixture
{
  std::string Out;
  vtkNew<vtkUnstructuredGrid> Grid, United;
  psitest::TransferFunction TF{ 2.0 };
  vtkNew<vtkPsiVolumeMapper> UnionMapper;
  std::unique_ptr<psitest::VolumeView> One;
  std::unique_ptr<Scene> AB, BA;

  explicit Fixture(const std::string& out)
    : Out(out)
  {
    psitest::MakeWaveletTets(this->Grid, 5, 1.0);
    // the union: the Wavelet and its copy moved where the second volume's matrix places it
    vtkNew<vtkTransform> move;
    move->Translate(Offset[0], Offset[1], Offset[2]);
    vtkNew<vtkTransformFilter> moved;
    moved->SetTransform(move);
    moved->SetInputData(this->Grid);
    vtkNew<vtkAppendFilter> both;
    both->AddInputData(this->Grid);
    both->AddInputConnection(moved->GetOutputPort());
    both->Update();
    this->United->ShallowCopy(both->GetOutput());
    psitest::BlueWhiteRed(this->TF.Color, 40, 280);
    psitest::LinearOpacity(this->TF.Opacity, 40, 280, 0.0, 0.6);
    this->UnionMapper->SetInputData(this->United);
    psitest::ApplyRequested(this->UnionMapper.GetPointer());
    this->One.reset(new psitest::VolumeView(W, H, this->UnionMapper, this->TF.Property));
    this->AB.reset(new Scene(this->Grid, this->TF.Property, this->TF.Property, false));
    this->BA.reset(new Scene(this->Grid, this->TF.Property, this->TF.Property, true));
  }
};

// Two disjoint volumes: the image of their union, in both orders and three views.
void TestDisjointUnion(Fixture& f)
{
  // --- disjoint volumes: the image of their union, in both orders and three views
  for (int view = 0; view < 3; ++view)
  {
    const std::vector<double> ref = Draw(f.One->Window, f.One->Renderer, view);
    const std::vector<double> imgAB = Draw(f.AB->Window, f.AB->Renderer, view);
    const std::vector<double> imgBA = Draw(f.BA->Window, f.BA->Renderer, view);
    const double ab_ = psitest::LargestDifference(imgAB, ref);
    const double ba_ = psitest::LargestDifference(imgBA, ref);
    std::printf("view %d: two volumes against their union: largest %.1f/255 (%.1f/255 in the other "
                "order), mean %.4f/255\n",
      view, 255 * ab_, 255 * ba_, 255 * Mean(imgAB, ref));
    PSI_CHECK(Covered(ref) > W * H / 8 && ab_ <= 1.0 / 255 + 1e-9 && ba_ <= 1.0 / 255 + 1e-9,
      "view %d: both orders of two disjoint volumes are their union drawn as one within 1/255 "
      "(largest %.1f/255 and %.1f/255, mean %.3f/255; %d pixels covered)",
      view, 255 * ab_, 255 * ba_, 255 * Mean(imgAB, ref), Covered(ref));
    PSI_CHECK(f.AB->MapperA->GetNumberOfTetrahedra() + f.AB->MapperB->GetNumberOfTetrahedra() ==
        f.United->GetNumberOfCells(),
      "view %d: each volume reads out its own tetrahedra (%lld + %lld of %lld)", view,
      static_cast<long long>(f.AB->MapperA->GetNumberOfTetrahedra()),
      static_cast<long long>(f.AB->MapperB->GetNumberOfTetrahedra()),
      static_cast<long long>(f.United->GetNumberOfCells()));
    if (!f.Out.empty())
    {
      psitest::WritePng(f.Out + "/intermixed_union_" + std::to_string(view) + ".png", ref, W, H);
      psitest::WritePng(f.Out + "/intermixed_ab_" + std::to_string(view) + ".png", imgAB, W, H);
    }
  }
}

// Their own color maps and unit distances: independent of the order, and their own.
void TestOwnTransferFunctions(Fixture& f)
{
  // --- different transfer functions and unit distances: independent of the order
  psitest::TransferFunction other(0.5);
  psitest::BlueToYellow(other.Color, 40, 280);
  psitest::LinearOpacity(other.Opacity, 40, 280, 0.5, 0.05);
  Scene mixedAB(f.Grid, f.TF.Property, other.Property, false);
  Scene mixedBA(f.Grid, f.TF.Property, other.Property, true);
  Scene sameAB(f.Grid, f.TF.Property, f.TF.Property, false);
  for (int view = 0; view < 2; ++view)
  {
    const std::vector<double> a = Draw(mixedAB.Window, mixedAB.Renderer, view);
    const std::vector<double> b = Draw(mixedBA.Window, mixedBA.Renderer, view);
    const std::vector<double> same = Draw(sameAB.Window, sameAB.Renderer, view);
    PSI_CHECK(psitest::LargestDifference(a, b) <= 1.0 / 255 + 1e-9 &&
        psitest::LargestDifference(a, same) > 0.25,
      "view %d: two volumes with their own color maps and unit distances do not depend on the "
      "order (largest %.1f/255), and the second keeps its own (largest %.0f/255 from the scene "
      "with one transfer function)",
      view, 255 * psitest::LargestDifference(a, b), 255 * psitest::LargestDifference(a, same));
    if (!f.Out.empty())
    {
      psitest::WritePng(f.Out + "/intermixed_mixed_" + std::to_string(view) + ".png", a, W, H);
    }
  }
}

// An isosurface in each volume, in its own slot: the union's image with it.
void TestIsosurfaces(Fixture& f)
{
  // --- isosurfaces: each volume's, in its own slot; the union's image with the same isovalue
  for (vtkPsiVolumeMapper* m :
    { f.UnionMapper.GetPointer(), f.AB->MapperA.GetPointer(), f.AB->MapperB.GetPointer() })
  {
    m->SetIsosurfaceValues({ 150.0 });
    m->SetIsosurfaceOpacity(0.6);
  }
  // a value below the second volume's range, dropped (kept, it would fall into the first's slot)
  f.AB->MapperB->SetIsosurfaceValues({ 150.0, -83.0 });
  for (int view = 0; view < 2; ++view)
  {
    const std::vector<double> ref = Draw(f.One->Window, f.One->Renderer, view);
    const std::vector<double> img = Draw(f.AB->Window, f.AB->Renderer, view);
    std::printf("view %d: two volumes with isosurfaces against their union: largest %.1f/255\n",
      view, 255 * psitest::LargestDifference(img, ref));
    if (!f.Out.empty())
    {
      psitest::WritePng(
        f.Out + "/intermixed_iso_union_" + std::to_string(view) + ".png", ref, W, H);
      psitest::WritePng(f.Out + "/intermixed_iso_ab_" + std::to_string(view) + ".png", img, W, H);
    }
    PSI_CHECK(psitest::LargestDifference(img, ref) <= 2.0 / 255 + 1e-9 &&
        f.AB->MapperA->GetLastUsedIsosurfaceMethod() >= 0,
      "view %d: two volumes with an isosurface each are their union with it (largest %.1f/255)",
      view, 255 * psitest::LargestDifference(img, ref));
  }
  for (vtkPsiVolumeMapper* m :
    { f.UnionMapper.GetPointer(), f.AB->MapperA.GetPointer(), f.AB->MapperB.GetPointer() })
  {
    m->SetIsosurfaceValues({});
  }
}

// One mesh split into two volumes at an interface: the whole mesh's image.
void TestInterface(Fixture& f)
{
  // --- an interface: one mesh split into two volumes, each with its own points on the shared
  // faces, draws as the whole mesh (MPVONC orders the tetrahedra across the interface as within
  // one mesh: the volumes' points welded by position)
  auto lower = Side(f.Grid, true), upper = Side(f.Grid, false);
  vtkNew<vtkPsiVolumeMapper> wholeMapper, lowerMapper, upperMapper;
  wholeMapper->SetInputData(f.Grid);
  lowerMapper->SetInputData(lower);
  upperMapper->SetInputData(upper);
  psitest::VolumeView whole(W, H, wholeMapper, f.TF.Property);
  psitest::VolumeView split(W, H, lowerMapper, f.TF.Property);
  vtkNew<vtkVolume> upperVolume;
  upperVolume->SetMapper(upperMapper);
  upperVolume->SetProperty(f.TF.Property);
  split.Renderer->AddVolume(upperVolume);
  for (vtkPsiVolumeMapper* m :
    { wholeMapper.GetPointer(), lowerMapper.GetPointer(), upperMapper.GetPointer() })
  {
    psitest::ApplyRequested(m);
  }
  for (int view = 0; view < 3; ++view)
  {
    whole.Renderer->GetActiveCamera()->DeepCopy(f.AB->Renderer->GetActiveCamera());
    SetView(whole.Renderer, view);
    const std::vector<double> a = psitest::GrabRGB(whole.Window);
    SetView(split.Renderer, view);
    const std::vector<double> b = psitest::GrabRGB(split.Window);
    std::printf("view %d: a mesh split into two volumes at an interface against the whole mesh: "
                "largest %.1f/255\n",
      view, 255 * psitest::LargestDifference(a, b));
    PSI_CHECK(lower->GetNumberOfCells() > 0 && upper->GetNumberOfCells() > 0 &&
        psitest::LargestDifference(a, b) <= 1.0 / 255 + 1e-9,
      "view %d: a mesh split into two volumes at an interface draws as the whole mesh (largest "
      "%.1f/255)",
      view, 255 * psitest::LargestDifference(a, b));
  }
}

// The camera inside one volume, then an opaque plane through both: the union's image.
void TestInsideAndOpaque(Fixture& f)
{
  // --- the camera inside one of them, and an opaque plane through both: the union's image
  for (vtkRenderer* ren : { f.One->Renderer.GetPointer(), f.AB->Renderer.GetPointer() })
  {
    psitest::SetCameraInside(ren->GetActiveCamera());
  }
  {
    const std::vector<double> ref = psitest::GrabRGB(f.One->Window);
    const std::vector<double> img = psitest::GrabRGB(f.AB->Window);
    std::printf("camera inside the first volume, against the union: largest %.1f/255 (near-plane "
                "path %d)\n",
      255 * psitest::LargestDifference(img, ref),
      static_cast<int>(f.AB->MapperA->GetLastUsedNearPlaneClipping()));
    PSI_CHECK(psitest::LargestDifference(img, ref) <= 1.0 / 255 + 1e-9 &&
        f.AB->MapperA->GetLastUsedNearPlaneClipping() && Covered(ref) > W * H / 4,
      "the camera inside one of two volumes: the union's image (largest %.1f/255)",
      255 * psitest::LargestDifference(img, ref));
  }
  vtkSmartPointer<vtkActor> opaqueOne = psitest::MakeOpaquePlane(6),
                            opaqueAB = psitest::MakeOpaquePlane(6);
  f.One->Renderer->AddActor(opaqueOne);
  f.AB->Renderer->AddActor(opaqueAB);
  for (int view = 0; view < 2; ++view)
  {
    const std::vector<double> ref = Draw(f.One->Window, f.One->Renderer, view);
    const std::vector<double> img = Draw(f.AB->Window, f.AB->Renderer, view);
    PSI_CHECK(psitest::LargestDifference(img, ref) <= 1.0 / 255 + 1e-9,
      "view %d: an opaque plane through two volumes: the union's image (largest %.1f/255)", view,
      255 * psitest::LargestDifference(img, ref));
  }
  f.One->Renderer->RemoveActor(opaqueOne);
  f.AB->Renderer->RemoveActor(opaqueAB);
}

// A translucent plane through both within dual depth peeling: the union's image.
void TestTranslucent(Fixture& f)
{
  // --- translucent geometry through both, within depth peeling: still the union's image
  AddTranslucentPlane(f.One->Window, f.One->Renderer);
  AddTranslucentPlane(f.AB->Window, f.AB->Renderer);
  for (int view = 0; view < 2; ++view)
  {
    const std::vector<double> ref = Draw(f.One->Window, f.One->Renderer, view);
    const std::vector<double> img = Draw(f.AB->Window, f.AB->Renderer, view);
    std::printf("view %d: with a translucent plane through both (depth peeling) against their "
                "union: largest %.1f/255\n",
      view, 255 * psitest::LargestDifference(img, ref));
    PSI_CHECK(psitest::LargestDifference(img, ref) <= 1.0 / 255 + 1e-9,
      "view %d: a translucent plane through two volumes within depth peeling: the union's image "
      "(largest %.1f/255)",
      view, 255 * psitest::LargestDifference(img, ref));
    if (!f.Out.empty())
    {
      psitest::WritePng(f.Out + "/intermixed_peel_" + std::to_string(view) + ".png", img, W, H);
    }
  }
  f.AB->Renderer->RemoveAllViewProps();
  f.AB->Renderer->AddVolume(f.AB->A);
  f.AB->Renderer->AddVolume(f.AB->B);
  f.AB->Renderer->SetUseDepthPeeling(0);
}

// Adaptive sampling: each volume's nodes in its slot. A narrow opacity spike that a 64-sample
// table misses: the union's image with adaptive sampling, and not the table's.
void TestAdaptive(Fixture& f)
{
  psitest::TransferFunction spike(2.0);
  psitest::BlueWhiteRed(spike.Color, 40, 280);
  for (const double* p : { (const double[]){ 40, 0 }, (const double[]){ 147, 0 },
         (const double[]){ 150, 0.9 }, (const double[]){ 153, 0 }, (const double[]){ 280, 0 } })
  {
    spike.Opacity->AddPoint(p[0], p[1]);
  }
  Scene two(f.Grid, spike.Property, spike.Property, false);
  vtkNew<vtkPsiVolumeMapper> unionMapper;
  unionMapper->SetInputData(f.United);
  psitest::VolumeView one(W, H, unionMapper, spike.Property);
  for (vtkPsiVolumeMapper* m :
    { unionMapper.GetPointer(), two.MapperA.GetPointer(), two.MapperB.GetPointer() })
  {
    psitest::ApplyRequested(m);
    m->SetTransferFunctionSamples(64);
    m->SetAdaptiveSampling(psi::AdaptiveModes::On);
  }
  const std::vector<double> ref = Draw(one.Window, one.Renderer, 0);
  const std::vector<double> adaptive = Draw(two.Window, two.Renderer, 0);
  const int nodes = two.MapperA->GetLastNumberOfAdaptiveNodes();
  two.MapperA->SetAdaptiveSampling(psi::AdaptiveModes::Off);
  const std::vector<double> table = Draw(two.Window, two.Renderer, 0);
  std::printf("adaptive sampling of a narrow spike: two volumes against their union %.1f/255 (%d "
              "nodes), the 64-sample table %.1f/255\n",
    255 * psitest::LargestDifference(adaptive, ref), nodes,
    255 * psitest::LargestDifference(table, ref));
  PSI_CHECK(psitest::LargestDifference(adaptive, ref) <= 1.0 / 255 + 1e-9 && nodes > 0 &&
      psitest::LargestDifference(table, ref) > 4.0 / 255,
    "adaptive sampling in the combined draw: each volume's nodes, the union's image (largest "
    "%.1f/255, %d nodes; the table alone %.1f/255)",
    255 * psitest::LargestDifference(adaptive, ref), nodes,
    255 * psitest::LargestDifference(table, ref));
}

// One hidden: the other alone.
void TestHidden(Fixture& f)
{
  // --- hiding one gives the other alone
  vtkNew<vtkPsiVolumeMapper> aloneMapper;
  aloneMapper->SetInputData(f.Grid);
  psitest::ApplyRequested(aloneMapper.GetPointer());
  psitest::VolumeView alone(W, H, aloneMapper, f.TF.Property);
  f.AB->B->VisibilityOff();
  const std::vector<double> hidden = Draw(f.AB->Window, f.AB->Renderer, 0);
  const std::vector<double> single = Draw(alone.Window, alone.Renderer, 0);
  PSI_CHECK(psitest::LargestDifference(hidden, single) <= 1.0 / 255 + 1e-9 &&
      f.AB->MapperA->GetNumberOfTetrahedra() == f.Grid->GetNumberOfCells(),
    "one volume hidden: the other alone (largest %.1f/255)",
    255 * psitest::LargestDifference(hidden, single));
}

int main(int argc, char* argv[])
{
  Fixture f(psitest::ParseArguments(argc, argv));
  TestDisjointUnion(f);
  TestOwnTransferFunctions(f);
  TestIsosurfaces(f);
  TestInterface(f);
  TestInsideAndOpaque(f);
  TestTranslucent(f);
  TestAdaptive(f);
  TestHidden(f);
  return psitest::Report("TestPsiIntermixedVolumes");
}
