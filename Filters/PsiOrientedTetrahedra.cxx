#include "PsiOrientedTetrahedra.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <utility>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
} // namespace

namespace psi
{
void OrientedTetrahedra::Add(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d, vtkIdType cellId)
{
  ++this->Generated;
  auto point = [this](vtkIdType i)
  {
    const double* x = this->Xyz + 3 * i;
    return Point3(x[0], x[1], x[2]);
  };
  switch (CGAL::orientation(point(a), point(b), point(c), point(d)))
  {
    case CGAL::COPLANAR:
      ++this->Removed;
      return;
    case CGAL::NEGATIVE:
      std::swap(c, d); // VTK's positive tetrahedron: (0,1,2) counterclockwise seen from 3
      break;
    default:
      break;
  }
  this->Connectivity.insert(this->Connectivity.end(), { a, b, c, d });
  this->Parent.push_back(cellId);
}

void OrientedTetrahedra::Reserve(size_t numTets)
{
  this->Connectivity.reserve(4 * numTets);
  this->Parent.reserve(numTets);
}
} // namespace psi
