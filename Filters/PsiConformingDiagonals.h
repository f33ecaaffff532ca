// PsiConformingDiagonals: the choice of face diagonals that makes a tetrahedralization conforming
// (neighbouring cells split their shared faces identically), as projected-tetrahedra renderers
// and MPVONC need (Williams 1992; Maximo et al. 2010 §3.1). GL-free; used by
// vtkPsiConformingTetrahedralize.
#ifndef PsiConformingDiagonals_h
#define PsiConformingDiagonals_h

#include "PsiCellFaces.h"

#include "vtkType.h"

namespace psi
{
class OrientedTetrahedra;

/// The conforming min-id split: every face is triangulated by the fan from its smallest id (a
/// quad by its min-id diagonal) and the cell is the cone from its smallest id over the faces
/// that do not contain it. The faces that do contain it are fans from it, i.e. the same rule, so
/// both cells sharing a face triangulate it identically whatever the cell types. Exact for convex
/// cells.
void ConeSplit(const FaceSet& faces, vtkIdType cellId, OrientedTetrahedra& tets);

/// The 5-tetrahedra split of hexahedron `hex` (VTK corner order), in the mirror image given by
/// the parity of i + j + k, so that the face diagonals of structured neighbours coincide.
void FivePerHexSplit(
  const vtkIdType hex[8], vtkIdType ijkSum, vtkIdType cellId, OrientedTetrahedra& tets);
} // namespace psi

#endif
