// Two volumes that share space, drawn intermixed (one visibility order of both meshes' cells),
// against the exact reference of two media (PsiReferenceMedia: where they overlap, attenuation
// and emission add). The intermixed draw composites each cell's segment of a ray whole, one after
// the other, so where cells of both overlap it is not exact: for two constant segments over the
// same length D the color differs by tau_1 tau_2 D^2 (L_2 - L_1) / 2 (to second order), with the
// sign of which is in front. The test measures, on the same two fields meshed with cells of 2, 1
// and 0.5 units (the volumes 12 units wide):
//  - that error alone, in exact arithmetic (the reference compositing each tetrahedron's piece
//    whole, in order): within the bound the README documents, and falling as the cells halve
//    (each halving at least to 0.7x);
//  - the intermixed image against the two media: within the renderer's own error on each volume
//    alone (against its own reference) plus that error.
// And two volumes that share no space but interleave in depth (slabs of each between slabs of
// the other, seven components), from three views with either sort: the exact image within the
// renderer's own error (largest 1.4-4/255 measured; one volume drawn over the other would be off
// by tens).
#include "PsiReferenceMedia.h"
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkAppendFilter.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
const int W = 128, H = 128;
const double Offset[3] = { 4.3, 2.7, 3.9 }; // the second volume's place: half inside the first
// The bound the README documents for the error of cells composited whole where the volumes
// overlap, on this scene: the largest channel error 8/255 and the mean 0.1/255 at cells of
// 2 units (1/6 of the volumes' width), proportional to the cells' size.
double BoundLargest(double cell)
{
  return 8.0 / 255 * cell / 2;
}
double BoundMean(double cell)
{
  return 0.1 / 255 * cell / 2;
}

// A smooth field of world position, so that every level meshes the same function.
double Field(const double p[3])
{
  return 160 + 100 * std::sin(0.35 * p[0] + 0.2) * std::cos(0.3 * p[1]) +
    40 * std::cos(0.25 * p[2]);
}

// The field at the points of `data`, as its point scalars.
void SetField(vtkDataSet* data)
{
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("field");
  scalars->SetNumberOfValues(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double p[3];
    data->GetPoint(i, p);
    scalars->SetValue(i, Field(p));
  }
  data->GetPointData()->SetScalars(scalars);
}

// The cube [-6, 6]^3 in Kuhn tetrahedra of side `cell`, the field at its points.
void MakeFieldMesh(vtkUnstructuredGrid* grid, double cell)
{
  const int half = static_cast<int>(std::lround(6 / cell));
  psitest::MakeKuhnWavelet(grid, half, cell);
  SetField(grid);
}

// The reference scene of `grid` moved by `offset` (as the volume's position moves it).
psi::ReferenceScene MovedScene(
  vtkUnstructuredGrid* grid, const psitest::TransferFunction& tf, const double offset[3])
{
  psi::ReferenceScene scene = psitest::MakeReferenceScene(grid, tf);
  for (auto& p : scene.Points)
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] += offset[k];
    }
  }
  return scene;
}

// Both scenes as one, each tetrahedron with its own scene's transfer function (the second's
// scalars shifted past the first's): the reference then composites each tetrahedron's piece of a
// ray whole, one after the other by entry, as the intermixed draw composites cells. Against the
// two media it shows the error of that alone, in exact arithmetic.
psi::ReferenceScene PieceOrderScene(const psi::ReferenceScene& a, const psi::ReferenceScene& b)
{
  const double shift = 1e4;
  psi::ReferenceScene both = a;
  const int first = static_cast<int>(a.Points.size());
  both.Points.insert(both.Points.end(), b.Points.begin(), b.Points.end());
  for (double v : b.Scalars)
  {
    both.Scalars.push_back(v + shift);
  }
  for (auto t : b.Tets)
  {
    both.Tets.push_back({ { t[0] + first, t[1] + first, t[2] + first, t[3] + first } });
  }
  for (double v : b.Breakpoints)
  {
    both.Breakpoints.push_back(v + shift);
  }
  const auto fa = a.Transfer, fb = b.Transfer;
  both.Transfer = [fa, fb, shift](double v, double out[4])
  { v < shift / 2 ? fa(v, out) : fb(v - shift, out); };
  return both;
}

struct Level
{
  psitest::Difference Mixed, Alone, Order;
};

// The two volumes' transfer functions: blue-white-red with opacity from `low` to `high`, and
// blue-to-yellow from `high` to `low`.
void TwoTransferFunctions(
  psitest::TransferFunction& a, psitest::TransferFunction& b, double low, double high)
{
  psitest::BlueWhiteRed(a.Color, 40, 280);
  psitest::LinearOpacity(a.Opacity, 40, 280, low, high);
  psitest::BlueToYellow(b.Color, 40, 280);
  psitest::LinearOpacity(b.Opacity, 40, 280, high, low);
}

// One cell size: the two volumes intermixed against the two media, and each alone against its
// own reference (the larger error of the two).
Level MeasureLevel(double cell, const std::string& out)
{
  const auto start = std::chrono::steady_clock::now();
  vtkNew<vtkUnstructuredGrid> grid;
  MakeFieldMesh(grid, cell);
  psitest::TransferFunction a(1.0), b(1.0);
  TwoTransferFunctions(a, b, 0.1, 0.8);
  vtkNew<vtkPsiVolumeMapper> mapperA, mapperB;
  mapperA->SetInputData(grid);
  mapperB->SetInputData(grid);
  psitest::ApplyRequested(mapperA.GetPointer());
  psitest::ApplyRequested(mapperB.GetPointer());
  psitest::VolumeView view(W, H, mapperA, a.Property);
  vtkNew<vtkVolume> second;
  second->SetMapper(mapperB);
  second->SetProperty(b.Property);
  second->SetPosition(Offset[0], Offset[1], Offset[2]);
  view.Renderer->AddVolume(second);
  vtkCamera* cam = view.Renderer->GetActiveCamera();
  cam->SetFocalPoint(2, 1.5, 2);
  cam->SetPosition(16, 22, 44);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(30);
  view.Renderer->ResetCameraClippingRange();
  const double none[3] = { 0, 0, 0 };
  const psi::ReferenceScene sa = MovedScene(grid, a, none), sb = MovedScene(grid, b, Offset);
  const psi::ReferenceCamera rc = psitest::ReferenceCameraOf(view.Renderer, W, H);
  Level level;
  const std::vector<double> gpu = psitest::GrabRGB(view.Window);
  const std::vector<double> ref = psi::RenderReferenceMedia({ &sa, &sb }, rc);
  level.Mixed = psitest::DifferenceFrom(gpu, ref);
  level.Order = psitest::DifferenceFrom(psi::RenderReference(PieceOrderScene(sa, sb), rc), ref);
  if (!out.empty())
  {
    const std::string name = out + "/interpenetrating_" + std::to_string(grid->GetNumberOfCells());
    psitest::WritePng(name + ".png", gpu, W, H);
    psitest::WritePng(name + "_reference.png", ref, W, H);
  }
  for (vtkVolume* alone : { view.Volume.GetPointer(), second.GetPointer() })
  {
    view.Volume->SetVisibility(alone == view.Volume.GetPointer());
    second->SetVisibility(alone == second.GetPointer());
    const psi::ReferenceScene& s = alone == second.GetPointer() ? sb : sa;
    const psitest::Difference e =
      psitest::DifferenceFrom(psitest::GrabRGB(view.Window), psi::RenderReference(s, rc));
    level.Alone.Max = std::max(level.Alone.Max, e.Max);
    level.Alone.Mean = std::max(level.Alone.Mean, e.Mean);
  }
  std::printf(
    "cells of %.2f (%lld tetrahedra each): intermixed against two media: largest "
    "%.1f/255, mean %.3f/255; each alone against its reference: largest %.1f/255, mean "
    "%.3f/255; cells composited whole in exact arithmetic: largest %.1f/255, mean %.3f/255\n",
    cell, static_cast<long long>(grid->GetNumberOfCells()), 255 * level.Mixed.Max,
    255 * level.Mixed.Mean, 255 * level.Alone.Max, 255 * level.Alone.Mean, 255 * level.Order.Max,
    255 * level.Order.Mean);
  std::printf(
    "  %.1f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return level;
}
// Slabs z0..z0+0.5 of [-6, 6]^2 (one cell thick in z), one per z0, as one mesh with the field.
vtkSmartPointer<vtkUnstructuredGrid> Slabs(const std::vector<double>& z0s)
{
  vtkNew<vtkAppendFilter> all;
  for (double z0 : z0s)
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(13, 13, 2);
    image->SetOrigin(-6, -6, z0);
    image->SetSpacing(1, 1, 0.5);
    SetField(image);
    vtkNew<vtkUnstructuredGrid> grid;
    psitest::TetrahedralizeImage(image, false, grid);
    all->AddInputData(grid);
  }
  all->MergePointsOn();
  all->Update();
  vtkSmartPointer<vtkUnstructuredGrid> out = all->GetOutput();
  return out;
}

// Two volumes that share no space but interleave in depth (slabs of one between slabs of the
// other: neither is in front of the other), each in several components: intermixed, against the
// exact reference, from three views, with either sort.
void TestInterleaved(const std::string& out)
{
  auto a = Slabs({ -3, -1, 1, 3 }), b = Slabs({ -2, 0, 2 });
  psitest::TransferFunction ta(1.0), tb(1.0);
  TwoTransferFunctions(ta, tb, 0.3, 0.8);
  vtkNew<vtkPsiVolumeMapper> mapperA, mapperB;
  mapperA->SetInputData(a);
  mapperB->SetInputData(b);
  psitest::VolumeView view(W, H, mapperA, ta.Property);
  vtkNew<vtkVolume> second;
  second->SetMapper(mapperB);
  second->SetProperty(tb.Property);
  view.Renderer->AddVolume(second);
  const double none[3] = { 0, 0, 0 };
  const psi::ReferenceScene sa = MovedScene(a, ta, none), sb = MovedScene(b, tb, none);
  const double eyes[3][3] = { { 6, 9, 30 }, { -5, 7, -30 }, { 28, 6, 9 } };
  for (psi::Sorts sort : { psi::Sorts::MPVONC, psi::Sorts::Centroid })
  {
    for (int v = 0; v < 3; ++v)
    {
      for (vtkPsiVolumeMapper* m : { mapperA.GetPointer(), mapperB.GetPointer() })
      {
        psitest::ApplyRequested(m);
        m->SetSortMethod(sort);
      }
      vtkCamera* cam = view.Renderer->GetActiveCamera();
      cam->SetFocalPoint(0, 0, 0);
      cam->SetPosition(eyes[v][0], eyes[v][1], eyes[v][2]);
      cam->SetViewUp(0, 1, 0);
      cam->SetViewAngle(30);
      view.Renderer->ResetCameraClippingRange();
      const std::vector<double> gpu = psitest::GrabRGB(view.Window);
      const std::vector<double> ref =
        psi::RenderReferenceMedia({ &sa, &sb }, psitest::ReferenceCameraOf(view.Renderer, W, H));
      const psitest::Difference e = psitest::DifferenceFrom(gpu, ref);
      std::printf("interleaved in depth, view %d, %s: largest %.1f/255, mean %.3f/255\n", v,
        sort == psi::Sorts::MPVONC ? "MPVONC" : "centroid", 255 * e.Max, 255 * e.Mean);
      PSI_CHECK(e.Max <= 6.0 / 255 && e.Mean <= 0.5 / 255,
        "interleaved in depth, view %d, sort %d: the exact image within the renderer's own error "
        "(largest %.1f/255 <= 6, mean %.3f/255 <= 0.5)",
        v, static_cast<int>(sort), 255 * e.Max, 255 * e.Mean);
      if (!out.empty() && sort == psi::Sorts::MPVONC)
      {
        psitest::WritePng(out + "/interleaved_" + std::to_string(v) + ".png", gpu, W, H);
      }
    }
  }
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string out = psitest::ParseArguments(argc, argv);
  TestInterleaved(out);
  const double cells[3] = { 2.0, 1.0, 0.5 };
  Level levels[3];
  for (int k = 0; k < 3; ++k)
  {
    const Level l = levels[k] = MeasureLevel(cells[k], out);
    PSI_CHECK(l.Order.Max <= BoundLargest(cells[k]) && l.Order.Mean <= BoundMean(cells[k]),
      "cells of %.2f: cells composited whole where two volumes overlap, within the documented "
      "bound of the two media (largest %.1f/255 <= %.1f/255, mean %.3f/255 <= %.3f/255)",
      cells[k], 255 * l.Order.Max, 255 * BoundLargest(cells[k]), 255 * l.Order.Mean,
      255 * BoundMean(cells[k]));
    PSI_CHECK(l.Mixed.Max <= l.Alone.Max + l.Order.Max + 1.0 / 255 &&
        l.Mixed.Mean <= l.Alone.Mean + l.Order.Mean + 0.1 / 255,
      "cells of %.2f: two interpenetrating volumes drawn intermixed within the renderer's own "
      "error plus that of cells composited whole (largest %.1f/255 <= %.1f + %.1f + 1, mean "
      "%.3f/255 <= %.3f + %.3f + 0.1)",
      cells[k], 255 * l.Mixed.Max, 255 * l.Alone.Max, 255 * l.Order.Max, 255 * l.Mixed.Mean,
      255 * l.Alone.Mean, 255 * l.Order.Mean);
  }
  for (int k = 1; k < 3; ++k)
  {
    PSI_CHECK(levels[k].Order.Max <= 0.7 * levels[k - 1].Order.Max &&
        levels[k].Order.Mean <= 0.7 * levels[k - 1].Order.Mean,
      "halving the cells (%.2f to %.2f) brings cells composited whole closer to the two media "
      "(largest %.1f/255 to %.1f/255, mean %.3f/255 to %.3f/255: each at most 0.7x)",
      cells[k - 1], cells[k], 255 * levels[k - 1].Order.Max, 255 * levels[k].Order.Max,
      255 * levels[k - 1].Order.Mean, 255 * levels[k].Order.Mean);
  }
  return psitest::Report("TestPsiInterpenetratingVolumes");
}
