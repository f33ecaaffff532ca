// Several volumes as one mesh (psi::IntermixMeshes and the concatenated tables, GL-free):
//  - every point lands where its volume's matrix places it, the shift at the centre of the
//    points the cells use;
//  - the concatenated table read at a point's slot scalar gives what the volume's own table
//    gives at its scalar, for every volume, at the ends of the range and between samples, with
//    different unit distances and ranges (each volume keeps its own attenuation);
//  - cells keep their points, moved by the volumes before them; with points welded by position
//    a face two volumes share makes their tetrahedra neighbours, as within one mesh;
//  - the opacity prefix counts continue across slots, and a separate opacity array of one volume
//    gives the others their color scalar's fraction;
//  - each volume's adaptive-sampling nodes land in its slot at the slot scalars of their own
//    scalars, with their values, in ascending order.
#include "PsiIntermixedMesh.h"
#include "PsiTestCheck.h"
#include "PsiTransferFunctionAnalysis.h"

#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <vector>

namespace
{
// Two tetrahedra sharing a face, scalar s = a + b x over the points.
vtkSmartPointer<vtkUnstructuredGrid> TwoTets(double a, double b)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  const double p[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (const auto& x : p)
  {
    pts->InsertNextPoint(x);
    s->InsertNextValue(a + b * x[0]);
  }
  grid->SetPoints(pts);
  grid->GetPointData()->SetScalars(s);
  const vtkIdType t0[4] = { 0, 1, 2, 3 }, t1[4] = { 1, 2, 3, 4 };
  grid->InsertNextCell(VTK_TETRA, 4, t0);
  grid->InsertNextCell(VTK_TETRA, 4, t1);
  return grid;
}

// One tetrahedron a b c d, scalar s = x.
vtkSmartPointer<vtkUnstructuredGrid> OneTet(
  const double* a, const double* b, const double* c, const double* d)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> s;
  for (const double* x : { a, b, c, d })
  {
    pts->InsertNextPoint(x);
    s->InsertNextValue(x[0]);
  }
  grid->SetPoints(pts);
  grid->GetPointData()->SetScalars(s);
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, ids);
  return grid;
}

vtkSmartPointer<vtkVolumeProperty> Property(double lo, double hi, double unitDistance)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.1, 0.2, 0.9);
  color->AddRGBPoint(0.3 * lo + 0.7 * hi, 1.0, 0.5, 0.0);
  color->AddRGBPoint(hi, 0.9, 0.9, 0.2);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(0.5 * (lo + hi), 0.8);
  opacity->AddPoint(hi, 0.1);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unitDistance);
  return property;
}

double Largest(const double a[4], const double b[4])
{
  double d = 0;
  for (int k = 0; k < 4; ++k)
  {
    d = std::max(d, std::abs(a[k] - b[k]));
  }
  return d;
}

// psi::IntermixNodes: two volumes' nodes over their own ranges as slot scalars.
void TestNodes(int samples)
{
  psi::TransferFunctionNodes a, b;
  a.Scalars = { 10, 12, 15 };
  a.Rgba = { 1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3 };
  a.MaxDeviation = 0.001;
  b.Scalars = { -3, -3, 1 }; // a step at -3
  b.Rgba = { 0, 0, 0, 4, 1, 1, 1, 5, 0.5f, 0.5f, 0.5f, 6 };
  b.MaxDeviation = 0.01;
  const psi::TransferFunctionNodes all =
    psi::IntermixNodes({ a, b }, { { { 10.0, 15.0 } }, { { -3.0, 1.0 } } }, samples);
  const double expect[6] = { psi::SlotScalar(0, 2, samples, 0.0),
    psi::SlotScalar(0, 2, samples, 0.4), psi::SlotScalar(0, 2, samples, 1.0),
    psi::SlotScalar(1, 2, samples, 0.0), psi::SlotScalar(1, 2, samples, 0.0),
    psi::SlotScalar(1, 2, samples, 1.0) };
  double worst = all.Size() == 6 ? 0 : 1;
  for (int i = 0; i < all.Size() && i < 6; ++i)
  {
    worst = std::max(worst, std::abs(all.Scalars[i] - expect[i]));
    worst = std::max(worst, i > 0 && all.Scalars[i] < all.Scalars[i - 1] ? 1.0 : 0.0);
  }
  PSI_CHECK(worst < 1e-12 && all.Rgba.size() == 24 && all.Rgba[3] == 1 && all.Rgba[23] == 6 &&
      all.MaxDeviation == 0.01,
    "each volume's nodes in its slot, ascending, with their values (%g off)", worst);
}
} // namespace

int main()
{
  const int samples = 64;
  auto g0 = TwoTets(10.0, 5.0), g1 = TwoTets(-3.0, 1.0);
  const psi::TetMesh m0 = psi::GatherTetMesh(g0, g0->GetPointData()->GetScalars(), false);
  const psi::TetMesh m1 = psi::GatherTetMesh(g1, g1->GetPointData()->GetScalars(), false);
  std::vector<psi::IntermixedVolume> volumes(2);
  volumes[0].Mesh = &m0;
  volumes[1].Mesh = &m1;
  // the second volume scaled by 2 and moved by (10, 0, -4)
  volumes[1].ModelToWorld = { { 2, 0, 0, 10, 0, 2, 0, 0, 0, 0, 2, -4, 0, 0, 0, 1 } };
  const psi::TetMesh all = psi::IntermixMeshes(volumes, samples);
  TestNodes(samples);

  // --- geometry
  PSI_CHECK(
    all.NumberOfPoints() == 10 && all.NumberOfTets() == 4, "points and cells of both volumes");
  const double expectShift[3] = { 6.0, 1.0, -1.5 }; // the centre of [0, 12] x [0, 2] x [-4, 1]
  double worst = 0;
  for (int k = 0; k < 3; ++k)
  {
    worst = std::max(worst, std::abs(all.Shift[k] - expectShift[k]));
  }
  for (int i = 0; i < 5; ++i)
  {
    double p[3];
    g1->GetPoint(i, p);
    const float* q = &all.Points4[4 * (5 + i)];
    worst = std::max(worst, std::abs(q[0] + all.Shift[0] - (2 * p[0] + 10)));
    worst = std::max(worst, std::abs(q[1] + all.Shift[1] - 2 * p[1]));
    worst = std::max(worst, std::abs(q[2] + all.Shift[2] - (2 * p[2] - 4)));
  }
  PSI_CHECK(worst < 1e-5, "the second volume's points placed by its matrix (%g off)", worst);
  PSI_CHECK(all.Tets[4] == 1 + 0 && all.Tets[8] == 5 + 0 && all.Tets[15] == 5 + 4,
    "cells keep their points, moved by the first volume's point count");
  PSI_CHECK(std::abs(all.MaxEdgeLength - 2 * std::sqrt(2.0)) < 1e-5,
    "edges measured in the world (the scaled volume's longest: %g)", all.MaxEdgeLength);

  // --- one table, each volume in its own slot
  auto p0 = Property(m0.ScalarRange[0], m0.ScalarRange[1], 1.0);
  auto p1 = Property(m1.ScalarRange[0], m1.ScalarRange[1], 0.25);
  const psi::TransferFunctionTable t0 = psi::SampleTransferFunction(p0, m0.ScalarRange, samples);
  const psi::TransferFunctionTable t1 = psi::SampleTransferFunction(p1, m1.ScalarRange, samples);
  const psi::TransferFunctionTable table = psi::IntermixTables({ t0, t1 });
  PSI_CHECK(table.Size == 2 * samples && table.Range[0] == 0 && table.Range[1] == 1,
    "the table: both slots over [0, 1]");
  worst = 0;
  const psi::TransferFunctionTable* own[2] = { &t0, &t1 };
  const psi::TetMesh* meshes[2] = { &m0, &m1 };
  for (int k = 0; k < 2; ++k)
  {
    const double* r = meshes[k]->ScalarRange;
    for (int j = 0; j <= 1000; ++j)
    {
      const double s = r[0] + (r[1] - r[0]) * j / 1000.0;
      double a[4], b[4];
      own[k]->Lookup(s, a);
      table.Lookup(psi::SlotScalar(k, 2, samples, psi::UnitScalar(r, s)), b);
      worst = std::max(worst, Largest(a, b));
    }
  }
  PSI_CHECK(worst < 1e-5,
    "the table at a slot scalar is the volume's own table at its scalar (%g off)", worst);
  double tau0[4], tau1[4];
  table.Lookup(psi::SlotScalar(0, 2, samples, 0.5), tau0);
  table.Lookup(psi::SlotScalar(1, 2, samples, 0.5), tau1);
  PSI_CHECK(std::abs(tau1[3] - 4 * tau0[3]) < 1e-4 * tau1[3],
    "each slot keeps its unit distance: attenuation 4x at a quarter of the distance (%g, %g)",
    tau0[3], tau1[3]);
  worst = 0;
  for (int i = 0; i < 10; ++i)
  {
    const int k = i < 5 ? 0 : 1;
    const double u = meshes[k]->Points4[4 * (i % 5) + 3];
    worst = std::max(worst, std::abs(all.Points4[4 * i + 3] - psi::SlotScalar(k, 2, samples, u)));
  }
  PSI_CHECK(worst < 1e-6, "the points carry their slot scalars (%g off)", worst);

  // --- opacity prefix counts continue across slots
  bool zero0 = false, zero1 = false;
  const std::vector<float> c0 = psi::OpacityPrefixCounts(t0, p0, zero0);
  const std::vector<float> c1 = psi::OpacityPrefixCounts(t1, p1, zero1);
  const std::vector<float> c = psi::IntermixOpacityPrefixes({ c0, c1 });
  PSI_CHECK(c.size() == 2 * size_t(samples) && c[samples - 1] == c0.back() &&
      c.back() == c0.back() + c1.back() && c[samples] == c0.back() + c1[0],
    "the opacity prefix counts of the second slot continue the first's");

  // --- neighbours: across a face shared by two volumes (points welded by position), none across
  // faces that only touch nothing
  const double corner[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
  auto lowerTet = OneTet(corner[0], corner[1], corner[2], corner[3]);
  auto upperTet = OneTet(corner[1], corner[2], corner[3], corner[4]); // shares face 1, 2, 3
  const psi::TetMesh ml =
    psi::GatherTetMesh(lowerTet, lowerTet->GetPointData()->GetScalars(), false);
  const psi::TetMesh mu =
    psi::GatherTetMesh(upperTet, upperTet->GetPointData()->GetScalars(), false);
  std::vector<psi::IntermixedVolume> touching(2);
  touching[0].Mesh = &ml;
  touching[1].Mesh = &mu;
  const std::vector<int32_t> across =
    psi::WeldedFaceNeighbors(psi::IntermixMeshes(touching, samples));
  // the first volume's face opposite its point 0 is the second's face opposite its point 3
  PSI_CHECK(across.size() == 8 && across[0] == 1 && across[7] == 0 && across[1] == -1,
    "across the face two volumes share, each other's neighbour (%d, %d)", across[0], across[7]);
  const std::vector<int32_t> apart = psi::WeldedFaceNeighbors(all);
  bool crosses = false;
  for (size_t i = 0; i < apart.size(); ++i)
  {
    crosses = crosses || (apart[i] >= 0 && (apart[i] >= 2) != (i >= 8));
  }
  PSI_CHECK(apart[0] == 1 && apart[8] == 3 && !crosses,
    "volumes apart: their own neighbours within, none between them");

  // --- a separate opacity array in one volume
  psi::TetMesh withOpacity = m0;
  withOpacity.Opacity.assign(m0.NumberOfPoints(), 0.25f);
  volumes[0].Mesh = &withOpacity;
  const psi::TetMesh mixed = psi::IntermixMeshes(volumes, samples);
  PSI_CHECK(mixed.Opacity.size() == 10 &&
      std::abs(mixed.Opacity[0] - psi::SlotScalar(0, 2, samples, 0.25)) < 1e-6 &&
      std::abs(mixed.Opacity[7] - mixed.Points4[4 * 7 + 3]) < 1e-6,
    "a separate opacity array: its slot scalars; the other volume reads its color scalar");
  return psitest::Report("TestIntermixedMesh");
}
