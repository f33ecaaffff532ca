// Checks of a tetrahedral mesh that are independent of the filter that made it: conformity
// (every interior triangle shared by exactly two tetrahedra, the unshared ones tiling the
// domain's surface), exact positive orientation (CGAL), volume, and FaceNeighbors and
// BoundaryFaces against a brute-force map of the triangles.
#ifndef PsiConformityCheck_h
#define PsiConformityCheck_h

#include "PsiTestCheck.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIntArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

namespace psitest
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
constexpr int FaceVerts[4][3] = { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 2 } };

/// The point ids of tetrahedron `t` of `ug`.
inline std::array<vtkIdType, 4> Tet(vtkUnstructuredGrid* ug, vtkIdType t)
{
  vtkIdType npts;
  const vtkIdType* p;
  ug->GetCells()->GetCellAtId(t, npts, p);
  return { p[0], p[1], p[2], p[3] };
}

/// What Check finds in a mesh.
struct MeshStats
{
  vtkIdType NonTets = 0, NonPositive = 0, OverShared = 0, BoundaryTriangles = 0;
  vtkIdType NeighborMismatches = 0, FlagMismatches = 0;
  double Volume = 0, BoundaryArea = 0;
};

/// Conformity, orientation and adjacency of a tetrahedral output, all independent of the filter:
/// exact CGAL orientation, a std::map of sorted triangles, areas and volumes in double.
inline MeshStats Check(vtkUnstructuredGrid* ug)
{
  MeshStats s;
  const vtkIdType n = ug->GetNumberOfCells();
  std::vector<Point3> P(ug->GetNumberOfPoints());
  for (vtkIdType i = 0; i < ug->GetNumberOfPoints(); ++i)
  {
    double x[3];
    ug->GetPoint(i, x);
    P[i] = Point3(x[0], x[1], x[2]);
  }
  std::map<std::array<vtkIdType, 3>, std::vector<std::pair<vtkIdType, int>>> tris;
  for (vtkIdType t = 0; t < n; ++t)
  {
    s.NonTets += ug->GetCellType(t) != VTK_TETRA;
    const auto v = Tet(ug, t);
    s.NonPositive += CGAL::orientation(P[v[0]], P[v[1]], P[v[2]], P[v[3]]) != CGAL::POSITIVE;
    s.Volume += CGAL::to_double(CGAL::volume(P[v[0]], P[v[1]], P[v[2]], P[v[3]]));
    for (int f = 0; f < 4; ++f)
    {
      std::array<vtkIdType, 3> k = { v[FaceVerts[f][0]], v[FaceVerts[f][1]], v[FaceVerts[f][2]] };
      std::sort(k.begin(), k.end());
      tris[k].emplace_back(t, f);
    }
  }
  std::vector<vtkIdType> expected(4 * n, -1);
  for (const auto& e : tris)
  {
    if (e.second.size() > 2)
    {
      ++s.OverShared;
    }
    else if (e.second.size() == 1)
    {
      ++s.BoundaryTriangles;
      s.BoundaryArea +=
        std::sqrt(CGAL::to_double(CGAL::squared_area(P[e.first[0]], P[e.first[1]], P[e.first[2]])));
    }
    else
    {
      expected[4 * e.second[0].first + e.second[0].second] = e.second[1].first;
      expected[4 * e.second[1].first + e.second[1].second] = e.second[0].first;
    }
  }
  auto* nb = vtkIntArray::SafeDownCast(ug->GetCellData()->GetArray("FaceNeighbors"));
  auto* flags = vtkUnsignedCharArray::SafeDownCast(ug->GetCellData()->GetArray("BoundaryFaces"));
  if (!nb || !flags || nb->GetNumberOfComponents() != 4 || nb->GetNumberOfTuples() != n)
  {
    s.NeighborMismatches = n ? n : 1;
    return s;
  }
  for (vtkIdType t = 0; t < n; ++t)
  {
    for (int f = 0; f < 4; ++f)
    {
      s.NeighborMismatches += nb->GetTypedComponent(t, f) != expected[4 * t + f];
      s.FlagMismatches += ((flags->GetValue(t) >> f) & 1) != (expected[4 * t + f] < 0 ? 1 : 0);
    }
  }
  return s;
}

/// Checks that `ug` is a conforming, positively oriented tetrahedralization of the box `bounds`
/// with the brute-force face neighbours, and prints its counts.
inline void ExpectConformingBox(const char* name, vtkUnstructuredGrid* ug, const double bounds[6])
{
  const MeshStats s = Check(ug);
  const double a = bounds[1] - bounds[0], b = bounds[3] - bounds[2], c = bounds[5] - bounds[4];
  const double area = 2 * (a * b + b * c + c * a), volume = a * b * c;
  PSI_CHECK(s.NonTets == 0, "%s: %lld cells are not tetrahedra", name, (long long)s.NonTets);
  PSI_CHECK(s.NonPositive == 0, "%s: %lld tetrahedra not positive", name, (long long)s.NonPositive);
  PSI_CHECK(s.OverShared == 0, "%s: %lld triangles in > 2 tets", name, (long long)s.OverShared);
  PSI_CHECK(std::abs(s.BoundaryArea - area) < 1e-9 * area,
    "%s: unshared triangles cover %.12g, the box surface is %.12g (a crack inside?)", name,
    s.BoundaryArea, area);
  PSI_CHECK(std::abs(s.Volume - volume) < 1e-9 * volume, "%s: volume %.12g vs box %.12g", name,
    s.Volume, volume);
  PSI_CHECK(s.NeighborMismatches == 0 && s.FlagMismatches == 0,
    "%s: FaceNeighbors differ from brute force in %lld entries, BoundaryFaces in %lld", name,
    (long long)s.NeighborMismatches, (long long)s.FlagMismatches);
  std::printf("%-34s %8lld tets, %7lld boundary triangles, none in > 2 tets; "
              "boundary area %.6g (box %.6g), volume %.6g (box %.6g)\n",
    name, (long long)ug->GetNumberOfCells(), (long long)s.BoundaryTriangles, s.BoundaryArea, area,
    s.Volume, volume);
}
} // namespace psitest

#endif
