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
#include "PsiLODImage.h"
#include "PsiTestCheck.h"
#include "PsiTestMeshes.h"

#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
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
          p[a] = idx[a] == n - 1 ? bounds[2 * a + 1]
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
    const int i = static_cast<int>(cube % (n - 1)), j = static_cast<int>((cube / (n - 1)) % (n - 1));
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

psi::LODImage Resample(vtkUnstructuredGrid* grid)
{
  psi::LODArrays arrays;
  arrays.Color = "s";
  return psi::ResampleForLOD(grid, arrays, psi::LODRegion(), psi::DefaultLODResolution, false);
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
  PSI_CHECK(wrong == 0 && hidden > 0, "an L shape: the points of the missing cube hidden, the "
    "others not (%lld wrong of %lld hidden)", static_cast<long long>(wrong),
    static_cast<long long>(hidden));
  PSI_CHECK(!lod.Image->GetCellGhostArray(), "an L shape: no lattice cell hidden");
}

void CheckNaNIsHidden()
{
  const double bounds[6] = { 0, 1, 0, 1, 0, 1 };
  vtkNew<vtkUnstructuredGrid> grid;
  MakeBoxMesh(grid, bounds, 3, [](int, int, int) { return false; });
  grid->GetPointData()->GetArray("s")->SetComponent(0, 0, std::numeric_limits<double>::quiet_NaN());
  const psi::LODImage lod = Resample(grid);
  vtkDataArray* s = lod.Image->GetPointData()->GetArray("s");
  vtkIdType finite = 0;
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    finite += std::isfinite(s->GetTuple1(i)) ? 1 : 0;
  }
  PSI_CHECK(finite == s->GetNumberOfTuples() && Hidden(lod.Image, 0) &&
      !Hidden(lod.Image, lod.Image->GetNumberOfPoints() - 1),
    "a NaN: the samples it reaches hidden, every value finite");
}
} // namespace

int main()
{
  CheckBoxFillsItsImage();
  CheckLShapeHidesTheMissingCube();
  CheckNaNIsHidden();
  return psitest::Report("TestLODImage");
}
