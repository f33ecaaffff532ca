// PsiCellPointBounds: the bounds of the points a dataset's cells use (GL-free).
//
// vtkDataSet::GetBounds spans every point of the list, also points that no cell references.
// Readers and filters that keep a shared point list (a multi-region file read one region at a
// time, a threshold that keeps the input's points) produce such points, near or far: a single
// unused point at (1e7, 1e7, 1e7) would stretch the mesh's coordinate shift, its level of
// detail's lattice and the ray's longest path over empty space. Everything the renderer derives
// from a mesh's extent uses these bounds instead.
#ifndef PsiCellPointBounds_h
#define PsiCellPointBounds_h

#include "PsiVolumeCoreModule.h"

class vtkDataSet;

namespace psi
{
/// The bounds (xmin, xmax, ymin, ymax, zmin, zmax) of the points that `input`'s cells use; the
/// dataset's own bounds when every point is used (then no more than one pass over the cells'
/// point ids). False, leaving `bounds` uninitialized (vtkMath::UninitializeBounds), when no
/// cell uses a point.
PSIVOLUMECORE_EXPORT bool CellPointBounds(vtkDataSet* input, double bounds[6]);
}

#endif
