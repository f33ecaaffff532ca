#include "PsiCellPointBounds.h"

#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkDataSet.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <vector>

namespace psi
{
namespace
{
template <typename Id>
void MarkIds(const Id* ids, vtkIdType n, std::vector<char>& used)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (ids[i] >= 0 && static_cast<size_t>(ids[i]) < used.size())
    {
      used[static_cast<size_t>(ids[i])] = 1;
    }
  }
}

// Marks in `used` the points of every cell: read in place from the connectivity array where the
// cells are a vtkUnstructuredGrid's in VTK's contiguous 32- or 64-bit storage, cell by cell
// otherwise (any vtkDataSet). Ids outside the point list mark nothing.
void MarkUsedPoints(vtkDataSet* input, std::vector<char>& used)
{
  auto* ug = vtkUnstructuredGrid::SafeDownCast(input);
  vtkCellArray* cells = ug ? ug->GetCells() : nullptr;
  vtkDataArray* ids = cells ? cells->GetConnectivityArray() : nullptr;
  if (ids && ids->HasStandardMemoryLayout() && ids->GetNumberOfComponents() == 1 &&
    (ids->GetDataType() == VTK_TYPE_INT64 || ids->GetDataType() == VTK_TYPE_INT32 ||
      ids->GetDataType() == VTK_ID_TYPE))
  {
    const vtkIdType n = ids->GetNumberOfValues();
    if (ids->GetDataTypeSize() == 8)
    {
      MarkIds(static_cast<const vtkTypeInt64*>(ids->GetVoidPointer(0)), n, used);
    }
    else
    {
      MarkIds(static_cast<const vtkTypeInt32*>(ids->GetVoidPointer(0)), n, used);
    }
    return;
  }
  vtkNew<vtkIdList> pts;
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    input->GetCellPoints(c, pts);
    MarkIds(pts->GetPointer(0), pts->GetNumberOfIds(), used);
  }
}
} // namespace

bool CellPointBounds(vtkDataSet* input, double bounds[6])
{
  vtkMath::UninitializeBounds(bounds);
  const vtkIdType np = input ? input->GetNumberOfPoints() : 0;
  if (np == 0 || input->GetNumberOfCells() == 0)
  {
    return false;
  }
  std::vector<char> used(static_cast<size_t>(np), 0);
  MarkUsedPoints(input, used);
  if (std::find(used.begin(), used.end(), 0) == used.end())
  {
    input->GetBounds(bounds); // every point is used (VTK keeps these bounds)
    return true;
  }
  vtkBoundingBox box;
  double p[3];
  for (vtkIdType i = 0; i < np; ++i)
  {
    if (used[i])
    {
      input->GetPoint(i, p);
      box.AddPoint(p);
    }
  }
  if (!box.IsValid())
  {
    return false;
  }
  box.GetBounds(bounds);
  return true;
}
} // namespace psi
