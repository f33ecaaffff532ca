#include "PsiConformingDiagonals.h"

#include "PsiOrientedTetrahedra.h"

#include <algorithm>

namespace
{
// The literature's 5-tetrahedra split of a hexahedron (VTK corner order), in its two mirror
// images; alternating them with the parity of i + j + k makes the face diagonals of structured
// neighbours coincide (even: diagonals 0-2, 0-5, 0-7, 2-5, 2-7, 5-7; odd: the other ones).
constexpr int FiveEven[5][4] = { { 1, 0, 2, 5 }, { 3, 0, 2, 7 }, { 4, 0, 5, 7 }, { 6, 2, 5, 7 },
  { 0, 2, 5, 7 } };
constexpr int FiveOdd[5][4] = { { 0, 1, 3, 4 }, { 2, 1, 3, 6 }, { 5, 1, 4, 6 }, { 7, 3, 4, 6 },
  { 1, 3, 4, 6 } };
} // namespace

namespace psi
{
void ConeSplit(const FaceSet& faces, vtkIdType cellId, OrientedTetrahedra& tets)
{
  if (faces.Ids.empty())
  {
    return;
  }
  const vtkIdType apex = *std::min_element(faces.Ids.begin(), faces.Ids.end());
  for (size_t f = 0; f + 1 < faces.Offsets.size(); ++f)
  {
    const vtkIdType* p = faces.Ids.data() + faces.Offsets[f];
    const vtkIdType n = faces.Offsets[f + 1] - faces.Offsets[f];
    if (n < 3 || std::find(p, p + n, apex) != p + n)
    {
      continue;
    }
    const vtkIdType k = std::min_element(p, p + n) - p;
    for (vtkIdType j = 1; j + 1 < n; ++j)
    {
      tets.Add(apex, p[k], p[(k + j) % n], p[(k + j + 1) % n], cellId);
    }
  }
}

void FivePerHexSplit(
  const vtkIdType hex[8], vtkIdType ijkSum, vtkIdType cellId, OrientedTetrahedra& tets)
{
  const auto& split = (ijkSum % 2 == 0) ? FiveEven : FiveOdd;
  for (const auto& t : split)
  {
    tets.Add(hex[t[0]], hex[t[1]], hex[t[2]], hex[t[3]], cellId);
  }
}
} // namespace psi
