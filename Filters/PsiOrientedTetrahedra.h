// PsiOrientedTetrahedra: collects the tetrahedra a split produces, positively oriented by CGAL's
// exact orientation predicate, and drops the flat ones (zero volume, e.g. from collapsed grid
// edges). GL-free; used by vtkPsiConformingTetrahedralize.
#ifndef PsiOrientedTetrahedra_h
#define PsiOrientedTetrahedra_h

#include "vtkType.h"

#include <cstddef>
#include <vector>

namespace psi
{
class OrientedTetrahedra
{
public:
  /// `xyz` holds the point coordinates, 3 doubles per point; it must outlive this object.
  explicit OrientedTetrahedra(const double* xyz)
    : Xyz(xyz)
  {
  }

  /// Adds tetrahedron (a, b, c, d), child of input cell `cellId`: swapped to VTK's positive
  /// orientation ((a, b, c) counterclockwise seen from d) when negative, dropped when flat.
  void Add(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d, vtkIdType cellId);

  /// Room for `numTets` tetrahedra.
  void Reserve(size_t numTets);

  /// 4 point ids per kept tetrahedron.
  std::vector<vtkIdType> Connectivity;
  /// The input cell of each kept tetrahedron.
  std::vector<vtkIdType> Parent;
  /// Tetrahedra added, kept or not.
  vtkIdType Generated = 0;
  /// Flat tetrahedra dropped.
  vtkIdType Removed = 0;

private:
  const double* Xyz;
};
} // namespace psi

#endif
