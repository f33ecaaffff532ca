// The image of the interactive level of detail (psi::ResampleForLOD, PsiLODImage.cxx), without
// OpenGL: which lattice points it hides and which it keeps.
//  - A box whose x extent is the Blunt Fin's (-7.8157..14.3622, single-precision bounds): for it
//    vtkProbeFilter's floor((max - origin) / spacing) falls one point short on the upper face, so
//    a lattice spanning the bounds exactly lost its last layer (a missing slab). Every point of
//    the image must lie in the mesh, and then the image has no ghost array at all (the ray caster
//    tests none).
//  - An L-shaped mesh (a box of 2x2x1 cubes, one cube left out): exactly the lattice points in the
//    missing cube are hidden, and no lattice cell is (hiding the cells that touch a hidden point
//    would hide a layer inside the mesh along its boundary).
//  - A NaN at one mesh point: the samples interpolated from it are hidden, every value finite.
//  - The samples against VTK's vtkProbeFilter on a mesh of tetrahedra of various sizes and shapes:
//    the same lattice points inside, the same linear interpolation there.
//  - A point array and a cell array of one name: the association asked for is the one sampled.
//  - A build that throws (a lattice too large to allocate) leaves no image and one error, said
//    once, and the same inputs are not tried again; other inputs build.
//  - The ray caster's opacity function: 1 - exp(-a) of 'Psi Volume''s a, at the nodes and between.
//  - A slab 50 times thinner than wide: the ray caster samples it along its thin axis as finely as
//    its lattice (one sample per smallest spacing).
#include "PsiLODImage.h"
#include "PsiLatticeSampling.h"
#include "PsiLevelOfDetail.h"
#include "PsiTestCheck.h"
#include "PsiTestMeshes.h"

#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkDelaunay3D.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkProbeFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <limits>

namespace
{
// Kuhn tetrahedra of the n x n x n lattice of points spanning `bounds`, with the scalar x + 2y + 3z
// ("s"), leaving out the cubes for which `skip(i, j, k)` holds (i, j, k: the cube's first point).
template <typename Skip>
void MakeBoxMesh(vtkUnstructuredGrid* grid, const double bounds[6], int n, Skip skip)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat(); // as readers give them: the bounds are single precision
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const int idx[3] = { i, j, k };
        double p[3];
        for (int a = 0; a < 3; ++a)
        {
          p[a] = idx[a] == n - 1
            ? bounds[2 * a + 1]
            : bounds[2 * a] + (bounds[2 * a + 1] - bounds[2 * a]) * idx[a] / (n - 1);
        }
        points->InsertNextPoint(p);
        s->InsertNextValue(p[0] + 2 * p[1] + 3 * p[2]);
      }
    }
  }
  vtkNew<vtkUnstructuredGrid> all;
  all->SetPoints(points);
  psitest::AddKuhnTets(all, n);
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(s);
  grid->Allocate(all->GetNumberOfCells());
  for (vtkIdType c = 0; c < all->GetNumberOfCells(); ++c)
  {
    const vtkIdType cube = c / 6; // AddKuhnTets: 6 tetrahedra per cube, cubes in i, j, k order
    const int i = static_cast<int>(cube % (n - 1)),
              j = static_cast<int>((cube / (n - 1)) % (n - 1));
    const int k = static_cast<int>(cube / ((n - 1) * (n - 1)));
    if (!skip(i, j, k))
    {
      vtkIdType npts;
      const vtkIdType* ids;
      all->GetCellPoints(c, npts, ids);
      grid->InsertNextCell(VTK_TETRA, npts, ids);
    }
  }
}

bool Hidden(vtkImageData* image, vtkIdType i)
{
  vtkUnsignedCharArray* ghosts = image->GetPointGhostArray();
  return ghosts && (ghosts->GetValue(i) & vtkDataSetAttributes::HIDDENPOINT);
}

psi::LODImage Resample(vtkUnstructuredGrid* grid, bool cells = false, int resolution = 64)
{
  psi::LODScalars scalars;
  scalars.Array = "s";
  scalars.Cells = cells;
  return psi::ResampleForLOD(grid, scalars, psi::LODRegion(), resolution);
}

vtkDataArray* Samples(const psi::LODImage& lod)
{
  return lod.Image->GetPointData()->GetArray(psi::LODArrayName);
}

void CheckBoxFillsItsImage()
{
  const double bounds[6] = { -7.815747261047363, 14.362203598022461, 0, 8.327558517456055, 0,
    5.7242512702941895 };
  vtkNew<vtkUnstructuredGrid> grid;
  MakeBoxMesh(grid, bounds, 2, [](int, int, int) { return false; });
  const psi::LODImage lod = Resample(grid);
  vtkIdType hidden = 0;
  for (vtkIdType i = 0; i < lod.Image->GetNumberOfPoints(); ++i)
  {
    hidden += Hidden(lod.Image, i) ? 1 : 0;
  }
  PSI_CHECK(hidden == 0 && !lod.Image->GetPointGhostArray() && !lod.Image->GetCellGhostArray(),
    "a box: every lattice point in the mesh, no ghost array (%lld hidden)",
    static_cast<long long>(hidden));
  const double* b = lod.Image->GetBounds();
  PSI_CHECK(b[0] >= bounds[0] && b[1] <= bounds[1] && b[1] - b[0] > 0.999 * (bounds[1] - bounds[0]),
    "the lattice spans the bounds, inside them");
}

void CheckLShapeHidesTheMissingCube()
{
  const double bounds[6] = { 0, 2, 0, 2, 0, 1 };
  vtkNew<vtkUnstructuredGrid> grid;
  MakeBoxMesh(grid, bounds, 3, [](int i, int j, int k) { return i == 1 && j == 1 && k <= 1; });
  const psi::LODImage lod = Resample(grid);
  vtkIdType wrong = 0, hidden = 0;
  const double eps = 1e-9;
  for (vtkIdType i = 0; i < lod.Image->GetNumberOfPoints(); ++i)
  {
    const double* p = lod.Image->GetPoint(i);
    const bool outside = p[0] > 1 + eps && p[1] > 1 + eps;
    const bool inside = p[0] < 1 - eps || p[1] < 1 - eps;
    hidden += Hidden(lod.Image, i) ? 1 : 0;
    wrong += (outside && !Hidden(lod.Image, i)) || (inside && Hidden(lod.Image, i)) ? 1 : 0;
  }
  PSI_CHECK(wrong == 0 && hidden > 0,
    "an L shape: the points of the missing cube hidden, the "
    "others not (%lld wrong of %lld hidden)",
    static_cast<long long>(wrong), static_cast<long long>(hidden));
  PSI_CHECK(!lod.Image->GetCellGhostArray(), "an L shape: no lattice cell hidden");
}

void CheckNaNIsHidden()
{
  const double bounds[6] = { 0, 1, 0, 1, 0, 1 };
  vtkNew<vtkUnstructuredGrid> grid;
  MakeBoxMesh(grid, bounds, 3, [](int, int, int) { return false; });
  grid->GetPointData()->GetArray("s")->SetComponent(0, 0, std::numeric_limits<double>::quiet_NaN());
  const psi::LODImage lod = Resample(grid);
  vtkDataArray* s = Samples(lod);
  vtkIdType finite = 0;
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    finite += std::isfinite(s->GetTuple1(i)) ? 1 : 0;
  }
  PSI_CHECK(finite == s->GetNumberOfTuples() && Hidden(lod.Image, 0) &&
      !Hidden(lod.Image, lod.Image->GetNumberOfPoints() - 1),
    "a NaN: the samples it reaches hidden, every value finite");
}
// A Delaunay tetrahedralization of random points in a box (tetrahedra of every size and shape,
// some slivers) with the scalar sin(x) + y z.
void MakeRandomMesh(vtkUnstructuredGrid* grid, int points)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkPoints> pts;
  for (int i = 0; i < points; ++i)
  {
    double p[3];
    for (double& x : p)
    {
      x = random->GetRangeValue(-1, 2);
      random->Next();
    }
    pts->InsertNextPoint(p);
  }
  vtkNew<vtkUnstructuredGrid> cloud;
  cloud->SetPoints(pts);
  vtkNew<vtkDelaunay3D> delaunay;
  delaunay->SetInputData(cloud);
  delaunay->Update();
  grid->ShallowCopy(delaunay->GetOutput());
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    const double* p = grid->GetPoint(i);
    s->InsertNextValue(std::sin(p[0]) + p[1] * p[2]);
  }
  grid->GetPointData()->AddArray(s);
}

void CheckAgainstProbeFilter()
{
  vtkNew<vtkUnstructuredGrid> grid;
  MakeRandomMesh(grid, 400);
  const int resolution = 24;
  const psi::LODImage lod = Resample(grid, false, resolution);
  vtkNew<vtkImageData> lattice; // the same lattice, without the image's arrays or ghosts
  lattice->SetOrigin(lod.Image->GetOrigin());
  lattice->SetSpacing(lod.Image->GetSpacing());
  lattice->SetDimensions(lod.Image->GetDimensions());
  vtkNew<vtkProbeFilter> probe;
  probe->SetInputData(lattice);
  probe->SetSourceData(grid);
  probe->Update();
  vtkDataArray* valid =
    probe->GetOutput()->GetPointData()->GetArray(probe->GetValidPointMaskArrayName());
  vtkDataArray* expected = probe->GetOutput()->GetPointData()->GetArray("s");
  vtkDataArray* got = Samples(lod);
  vtkIdType both = 0, disagree = 0;
  double worst = 0;
  for (vtkIdType i = 0; i < lattice->GetNumberOfPoints(); ++i)
  {
    const bool in = !Hidden(lod.Image, i), probed = valid->GetTuple1(i) != 0;
    disagree += in != probed ? 1 : 0;
    if (in && probed)
    {
      ++both;
      worst = std::max(worst, std::abs(got->GetTuple1(i) - expected->GetTuple1(i)));
    }
  }
  // The mesh the full frame draws has single-precision points: in Delaunay's slivers (heights of
  // 1e-4) a rounding of 1e-7 moves barycentric coordinates by 1e-3, hence the bound, 1e-3 of the
  // scalar's range (about 4): far below a color map's 1/255.
  PSI_CHECK(disagree == 0 && both > 1000 && worst < 4e-3,
    "random Delaunay mesh (%lld tetrahedra) against vtkProbeFilter: %lld of %lld points inside "
    "on one side only, largest difference %.3g over %lld",
    static_cast<long long>(grid->GetNumberOfCells()), static_cast<long long>(disagree),
    static_cast<long long>(lattice->GetNumberOfPoints()), worst, static_cast<long long>(both));
}

// Point data s = x; cell data s = -(x of the cell's centre) (as Point Data to Cell Data, passing
// the point data, then a cell Calculator writing s = -s).
void CheckAssociationOfOneName()
{
  const double bounds[6] = { 0, 1, 0, 1, 0, 1 };
  vtkNew<vtkUnstructuredGrid> grid;
  MakeBoxMesh(grid, bounds, 5, [](int, int, int) { return false; });
  vtkDataArray* point = grid->GetPointData()->GetArray("s");
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    point->SetTuple1(i, grid->GetPoint(i)[0]);
  }
  vtkNew<vtkDoubleArray> cell;
  cell->SetName("s");
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    double b[6];
    grid->GetCell(c)->GetBounds(b);
    cell->InsertNextValue(-(b[0] + b[1]) / 2);
  }
  grid->GetCellData()->AddArray(cell);
  const psi::LODImage points = Resample(grid, false), cells = Resample(grid, true);
  const vtkIdType far = points.Image->GetNumberOfPoints() - 1; // x = 1, y = 1, z = 1
  const double p = Samples(points)->GetTuple1(far), c = Samples(cells)->GetTuple1(far);
  PSI_CHECK(std::abs(p - 1) < 1e-3 && c < -0.8 && c > -1,
    "one name, two associations: the point array sampled as points (%g, want 1), the cell array "
    "as cells (%g, want the last cell's -0.875)",
    p, c);
}

void CheckThinSlabSampling()
{
  const double bounds[6] = { 0, 10, 0, 10, 0, 0.2 };
  vtkNew<vtkUnstructuredGrid> grid;
  MakeBoxMesh(grid, bounds, 3, [](int, int, int) { return false; });
  const psi::LODImage lod = Resample(grid);
  const double* h = lod.Image->GetSpacing();
  const double alongZ[3] = { 0, 0, -2 }, alongX[3] = { 1, 0, 0 };
  const double z = psi::LODSampleDistance(h, alongZ), x = psi::LODSampleDistance(h, alongX);
  PSI_CHECK(std::abs(z - h[2]) < 1e-9 * h[2] && std::abs(x - h[0]) < 1e-9 * h[0],
    "a slab 50 times thinner than wide: one sample per spacing along the thin axis (%g; %g) and "
    "along a wide one (%g; %g)",
    z, h[2], x, h[0]);
  const double cube[3] = { 0.5, 0.5, 0.5 }, diagonal[3] = { 1, -1, 1 };
  const double d = psi::LODSampleDistance(cube, diagonal);
  PSI_CHECK(std::abs(d - 0.5) < 1e-12, "a cubic lattice: its spacing along a diagonal (%g)", d);
}

// VTK's ray caster composites 1 - (1 - a')^(d / unit) per sample, 'Psi Volume' attenuates by
// exp(-a d / unit): equal for a' = 1 - exp(-a), everywhere along a ramp from 0 to 1.
void CheckRayCasterOpacity()
{
  vtkNew<vtkPiecewiseFunction> ramp, out;
  ramp->AddPoint(0, 0);
  ramp->AddPoint(10, 1);
  psi::LODOpacityFunction(ramp, out);
  double worst = 0;
  for (double x = 0; x <= 10; x += 0.125)
  {
    worst = std::max(worst, std::abs(out->GetValue(x) - (1 - std::exp(-ramp->GetValue(x)))));
  }
  PSI_CHECK(worst < 2e-3 && std::abs(out->GetValue(10) - (1 - std::exp(-1.0))) < 1e-12,
    "the ray caster's opacity 1 - exp(-a) along a ramp (worst %.2g)", worst);
}

void CheckFailedBuild()
{
  const double bounds[6] = { 0, 1, 0, 1, 0, 1 };
  vtkNew<vtkUnstructuredGrid> grid;
  MakeBoxMesh(grid, bounds, 3, [](int, int, int) { return false; });
  PsiLevelOfDetail lod;
  PsiLevelOfDetail::Scalars scalars;
  scalars.Array = "s";
  const int huge = 1 << 20; // 2^60 lattice points
  const bool built = lod.Update(grid, scalars, psi::LODRegion(), huge);
  const std::string first = lod.TakeNewError(), second = lod.TakeNewError();
  const bool again = lod.Update(grid, scalars, psi::LODRegion(), huge);
  PSI_CHECK(!built && !lod.HasImage() && !first.empty() && second.empty() && !again &&
      lod.TakeNewError().empty(),
    "a build that throws: no image, its error once ('%s'), not tried again", first.c_str());
  PSI_CHECK(lod.Update(grid, scalars, psi::LODRegion()) && lod.HasImage(),
    "after a failed build, other inputs build");
}

// Barycentric coordinates reproduce a point and reject a flat tetrahedron.
void CheckBarycentric()
{
  const double a[3] = { 0, 0, 0 }, b[3] = { 2, 0, 0 }, c[3] = { 0, 3, 0 }, d[3] = { 0, 0, 4 };
  const double p[3] = { 0.5, 0.75, 1 }, flat[3] = { 1, 1.5, 0 };
  double l[4];
  const bool ok = psi::Barycentric(a, b, c, d, p, l);
  double q[3];
  for (int k = 0; k < 3; ++k)
  {
    q[k] = l[0] * a[k] + l[1] * b[k] + l[2] * c[k] + l[3] * d[k];
  }
  PSI_CHECK(ok && std::abs(q[0] - p[0]) + std::abs(q[1] - p[1]) + std::abs(q[2] - p[2]) < 1e-12 &&
      std::abs(l[0] + l[1] + l[2] + l[3] - 1) < 1e-12,
    "barycentric coordinates reproduce the point");
  PSI_CHECK(!psi::Barycentric(a, b, c, flat, p, l), "a flat tetrahedron has none");
}
} // namespace

int main()
{
  CheckBoxFillsItsImage();
  CheckLShapeHidesTheMissingCube();
  CheckNaNIsHidden();
  CheckAgainstProbeFilter();
  CheckAssociationOfOneName();
  CheckThinSlabSampling();
  CheckBarycentric();
  CheckRayCasterOpacity();
  CheckFailedBuild();
  return psitest::Report("TestLODImage");
}
