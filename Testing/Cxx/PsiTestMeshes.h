// Tetrahedral meshes shared by the GL image tests: the Wavelet source split into tetrahedra
// (vtkDataSetTriangleFilter's split or Kuhn's), and Kuhn's split of any lattice of points.
#ifndef PsiTestMeshes_h
#define PsiTestMeshes_h

#include "vtkDataSetTriangleFilter.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRTAnalyticSource.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkUnstructuredGrid.h"

namespace psitest
{
/// Adds the 6 Kuhn tetrahedra around the main diagonal of every cube of a lattice of n^3 points
/// with ids i + n (j + n k) (the split of vtkPsiConformingTetrahedralize): long thin cells whose
/// centroid order is wrong across many shared faces.
inline void AddKuhnTets(vtkUnstructuredGrid* grid, int n)
{
  const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  for (int k = 0; k + 1 < n; ++k)
  {
    for (int j = 0; j + 1 < n; ++j)
    {
      for (int i = 0; i + 1 < n; ++i)
      {
        for (const auto& perm : perms)
        {
          int c[3] = { i, j, k };
          vtkIdType ids[4];
          ids[0] = c[0] + n * (c[1] + n * c[2]);
          for (int step = 0; step < 3; ++step)
          {
            ++c[perm[step]];
            ids[step + 1] = c[0] + n * (c[1] + n * c[2]);
          }
          grid->InsertNextCell(VTK_TETRA, 4, ids);
        }
      }
    }
  }
}

/// `image` (a cube of points, with point scalars) as tetrahedra: Kuhn's split (AddKuhnTets) or
/// vtkDataSetTriangleFilter's alternating one.
inline void TetrahedralizeImage(vtkImageData* image, bool kuhn, vtkUnstructuredGrid* grid)
{
  if (!kuhn)
  {
    vtkNew<vtkDataSetTriangleFilter> tets;
    tets->SetInputData(image);
    tets->Update();
    grid->ShallowCopy(tets->GetOutput());
    return;
  }
  vtkNew<vtkPoints> pts;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    pts->InsertNextPoint(image->GetPoint(i));
  }
  grid->SetPoints(pts);
  grid->GetPointData()->SetScalars(image->GetPointData()->GetScalars());
  AddKuhnTets(grid, image->GetDimensions()[0]);
}

/// The Wavelet source on [-half, half]^3, cells scaled to `cell` units, split into tetrahedra.
inline void MakeWaveletTets(vtkUnstructuredGrid* grid, int half, double cell)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-half, half, -half, half, -half, half);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(wavelet->GetOutputPort());
  vtkNew<vtkTransform> scale;
  scale->Scale(cell, cell, cell);
  vtkNew<vtkTransformFilter> scaled;
  scaled->SetTransform(scale);
  scaled->SetInputConnection(tets->GetOutputPort());
  scaled->Update();
  grid->ShallowCopy(scaled->GetOutput());
}

/// The Wavelet on [-half, half]^3 with cells of `cell` units, split into Kuhn tetrahedra
/// (AddKuhnTets).
inline void MakeKuhnWavelet(vtkUnstructuredGrid* grid, int half, double cell)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-half, half, -half, half, -half, half);
  wavelet->Update();
  vtkImageData* image = wavelet->GetOutput();
  const int n = 2 * half + 1;
  vtkNew<vtkPoints> points;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double p[3];
    image->GetPoint(i, p);
    points->InsertNextPoint(cell * p[0], cell * p[1], cell * p[2]);
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(image->GetPointData()->GetScalars());
  grid->Allocate(6 * (n - 1) * (n - 1) * (n - 1));
  AddKuhnTets(grid, n);
}
} // namespace psitest

#endif
