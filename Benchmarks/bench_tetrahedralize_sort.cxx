// Benchmark: vtkPsiConformingTetrahedralize, psi::ComputeTetNeighbors and the two
// visibility sorts of Maximo et al. 2010 §3.1 - the centroid sort (psi::SortBackToFront) and MPVONC
// (psi::SortMPVONC, Williams 1992) - on the NASA Blunt Fin (5 tetrahedra per hexahedron, as in
// the literature) and on a ~1M-tetrahedra mesh (a 56^3 image, 6 per hexahedron).
// Usage: bench_tetrahedralize_sort [DATA_DIR]
#include "PsiBluntFin.h"
#include "PsiCellCenterDepthSort.h"
#include "PsiMPVONCSort.h"
#include "PsiTetConnectivity.h"
#include "vtkPsiConformingTetrahedralize.h"

#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Best of `reps` runs (seconds).
template <class F>
double Best(int reps, F&& f)
{
  double best = 1e30;
  for (int r = 0; r < reps; ++r)
  {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, Since(t0));
  }
  return best;
}

void Row(const char* name, vtkDataSet* input, int mode)
{
  vtkNew<vtkPsiConformingTetrahedralize> filter;
  filter->SetSplitMode(mode);
  filter->SetInputData(input);
  const double tFilter = Best(3,
    [&]
    {
      filter->Modified();
      filter->Update();
    });
  vtkUnstructuredGrid* ug = filter->GetOutput();
  const size_t n = static_cast<size_t>(ug->GetNumberOfCells());
  std::vector<float> points4(4 * static_cast<size_t>(ug->GetNumberOfPoints()));
  double bounds[6];
  ug->GetBounds(bounds);
  for (vtkIdType i = 0; i < ug->GetNumberOfPoints(); ++i)
  {
    double x[3];
    ug->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
      points4[4 * i + k] = static_cast<float>(x[k]);
  }
  std::vector<uint32_t> tets(4 * n);
  for (size_t t = 0; t < n; ++t)
  {
    vtkIdType np;
    const vtkIdType* p;
    ug->GetCells()->GetCellAtId(static_cast<vtkIdType>(t), np, p);
    for (int k = 0; k < 4; ++k)
      tets[4 * t + k] = static_cast<uint32_t>(p[k]);
  }
  std::vector<int32_t> neighbors;
  const double tConn =
    Best(3, [&] { psi::ComputeTetNeighbors(tets.data(), n, points4.size() / 4, neighbors); });

  // Views: 8 perspective eyes on a sphere 2.5 diagonals around the centre.
  const double c[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double diag = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  double tCentroid = 0, tMPVONC = 0;
  size_t cycles = 0;
  const int views = 8;
  std::vector<uint32_t> order;
  for (int v = 0; v < views; ++v)
  {
    const double th = 0.7 + 2.1 * v, ph = 0.3 + 0.37 * v;
    const double eye[3] = { c[0] + 2.5 * diag * std::cos(th) * std::cos(ph),
      c[1] + 2.5 * diag * std::sin(th) * std::cos(ph), c[2] + 2.5 * diag * std::sin(ph) };
    tCentroid += Best(1,
      [&]
      {
        psi::SortBackToFront(
          psi::ComputeCentroids(points4.data(), tets.data(), n), eye, false, order);
      });
    psi::MPVONCResult r;
    tMPVONC += Best(1,
      [&] {
        r = psi::SortMPVONC(points4.data(), tets.data(), n, neighbors.data(), eye, false, order);
      });
    cycles += r.CyclesBroken;
  }
  std::printf("| %-28s | %9zu | %9lld | %10.3f | %12.3f | %13.1f | %10.1f | %11.1f |\n", name, n,
    (long long)filter->GetNumberOfRemovedDegenerateTets(), tFilter, tConn, 1e3 * tCentroid / views,
    1e3 * tMPVONC / views, double(cycles) / views);
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string dir = argc > 1 ? argv[1] : PSI_DATA_DIR;
  std::printf("vtkSMPTools backend %s, %d threads\n", vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  std::printf("| %-28s | %9s | %9s | %10s | %12s | %13s | %10s | %11s |\n", "mesh", "tets",
    "degen.", "filter s", "connect. s", "centroid ms", "MPVONC ms", "cycles/view");
  std::printf("|------------------------------|-----------|-----------|------------|--------------|"
              "---------------|------------|-------------|\n");
  if (vtkSmartPointer<vtkStructuredGrid> grid = psitest::ReadBluntFin(dir))
  {
    Row("Blunt Fin, five per hex", grid, vtkPsiConformingTetrahedralize::FIVE_PER_HEX);
    Row("Blunt Fin, conforming", grid, vtkPsiConformingTetrahedralize::CONFORMING);
  }
  else
  {
    std::printf("| Blunt Fin: %s/bluntfinxyz.bin not found, skipped\n", dir.c_str());
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(56, 56, 56);
  Row("56^3 image, conforming", image, vtkPsiConformingTetrahedralize::CONFORMING);
  Row("56^3 image, five per hex", image, vtkPsiConformingTetrahedralize::FIVE_PER_HEX);
  return 0;
}
