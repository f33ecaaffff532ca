// PsiFaceNeighborArrays: the face-adjacency cell arrays of a tetrahedral mesh, the input of
// MPVONC (Williams 1992; Maximo et al. 2010 §3.1), computed by psi::ComputeTetNeighbors.
// GL-free; used by vtkPsiConformingTetrahedralize.
#ifndef PsiFaceNeighborArrays_h
#define PsiFaceNeighborArrays_h

#include "vtkType.h"

#include <cstddef>
#include <vector>

class vtkCellData;

namespace psi
{
/// Adds to `cellData` the 4-component int array "FaceNeighbors" (face i opposite vertex i, -1 on
/// the boundary) and the bit-flag array "BoundaryFaces" (bit i: face i is on the boundary) of the
/// tetrahedra `connectivity` (4 point ids each, all below `numPoints`, which is below 2^32).
/// Returns the number of non-manifold faces (shared by more than two tetrahedra).
size_t AddFaceNeighborArrays(
  const std::vector<vtkIdType>& connectivity, vtkIdType numPoints, vtkCellData* cellData);
} // namespace psi

#endif
