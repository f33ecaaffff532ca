// PsiCellTypes: the cell-type array of an unstructured grid on every VTK the plugin builds
// against. VTK 9.6 keeps the types in any vtkDataArray (a vtkConstantArray when all cells share
// one type, as ParaView's own filters and vtkPsiConformingTetrahedralize make them) and
// deprecates GetCellTypesArray(), which has to convert such an array into a new one at each call.
#ifndef PsiCellTypes_h
#define PsiCellTypes_h

#include "vtkDataArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVersionMacros.h"

namespace psi
{
/// The grid's own array of cell types (one value per cell), never a converted copy.
inline vtkDataArray* CellTypesOf(vtkUnstructuredGrid* ug)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 0)
  return ug->GetCellTypes();
#else
  return ug->GetCellTypesArray();
#endif
}
} // namespace psi

#endif
