#include "PsiFaceNeighborArrays.h"

#include "PsiParallel.h"
#include "PsiTetConnectivity.h"

#include "vtkCellData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdint>

namespace psi
{
size_t AddFaceNeighborArrays(
  const std::vector<vtkIdType>& connectivity, vtkIdType numPoints, vtkCellData* cellData)
{
  const vtkIdType numTets = static_cast<vtkIdType>(connectivity.size() / 4);
  std::vector<uint32_t> tets32(connectivity.begin(), connectivity.end());
  std::vector<int32_t> neighbors;
  psi::TetConnectivityResult conn;
  std::vector<uint8_t> flags;
  // on threads even under ParaView's Sequential default (psi::Parallel)
  psi::Parallel(
    [&]
    {
      conn = psi::ComputeTetNeighbors(
        tets32.data(), static_cast<size_t>(numTets), static_cast<size_t>(numPoints), neighbors);
      flags = psi::BoundaryFaceFlags(neighbors);
    });

  vtkNew<vtkIntArray> faceNeighbors;
  faceNeighbors->SetName("FaceNeighbors");
  faceNeighbors->SetNumberOfComponents(4);
  faceNeighbors->SetNumberOfTuples(numTets);
  std::copy(neighbors.begin(), neighbors.end(), faceNeighbors->GetPointer(0));
  cellData->AddArray(faceNeighbors);

  vtkNew<vtkUnsignedCharArray> boundary;
  boundary->SetName("BoundaryFaces");
  boundary->SetNumberOfTuples(numTets);
  std::copy(flags.begin(), flags.end(), boundary->GetPointer(0));
  cellData->AddArray(boundary);
  return conn.NonManifoldFaces;
}
} // namespace psi
