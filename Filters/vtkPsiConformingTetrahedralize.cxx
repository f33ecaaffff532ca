#include "vtkPsiConformingTetrahedralize.h"

#include "PsiCellFaces.h"
#include "PsiConformingDiagonals.h"
#include "PsiFaceNeighborArrays.h"
#include "PsiOrientedTetrahedra.h"
#include "PsiParallel.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRectilinearGrid.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkPsiConformingTetrahedralize);

namespace
{
// The point dimensions of image, rectilinear and structured grids; zeros for other data sets.
void StructuredDimensions(vtkDataSet* input, int dims[3])
{
  dims[0] = dims[1] = dims[2] = 0;
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    image->GetDimensions(dims);
  }
  else if (auto* rgrid = vtkRectilinearGrid::SafeDownCast(input))
  {
    rgrid->GetDimensions(dims);
  }
  else if (auto* sgrid = vtkStructuredGrid::SafeDownCast(input))
  {
    sgrid->GetDimensions(dims);
  }
}

// The input's points: shared with a point set, generated for implicit grids.
vtkSmartPointer<vtkPoints> InputPoints(vtkDataSet* input)
{
  vtkSmartPointer<vtkPoints> points;
  if (auto* ps = vtkPointSet::SafeDownCast(input))
  {
    points = ps->GetPoints();
  }
  if (!points)
  {
    const vtkIdType numPoints = input->GetNumberOfPoints();
    points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(numPoints);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      double x[3];
      input->GetPoint(i, x);
      points->SetPoint(i, x);
    }
  }
  return points;
}

// The coordinates of `points` as doubles, 3 per point, for the exact orientation predicate; on
// threads even under ParaView's Sequential default (psi::Parallel).
std::vector<double> DoubleCoordinates(vtkPoints* points, vtkIdType numPoints)
{
  std::vector<double> xyz(3 * static_cast<size_t>(numPoints));
  psi::Parallel(
    [&]
    {
      vtkSMPTools::For(0, numPoints,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            points->GetPoint(i, xyz.data() + 3 * i);
          }
        });
    });
  return xyz;
}

// Hidden (blanked) cells, which are skipped: IBLANK of PLOT3D grids, for instance.
class HiddenCells
{
public:
  explicit HiddenCells(vtkDataSet* input)
    : SGrid(vtkStructuredGrid::SafeDownCast(input))
    , Ghosts(input->GetCellData()->GetGhostArray())
  {
    this->SGridBlanking =
      this->SGrid && (this->SGrid->HasAnyBlankCells() || this->SGrid->HasAnyBlankPoints());
  }

  bool operator()(vtkIdType cellId) const
  {
    if (this->SGridBlanking)
    {
      return !this->SGrid->IsCellVisible(cellId);
    }
    return this->Ghosts && (this->Ghosts->GetValue(cellId) & vtkDataSetAttributes::HIDDENCELL);
  }

private:
  vtkStructuredGrid* SGrid;
  vtkUnsignedCharArray* Ghosts;
  bool SGridBlanking = false;
};

// Adds a one-value vtkIdType array to the field data of `output`.
void AddCount(vtkUnstructuredGrid* output, const char* name, vtkIdType value)
{
  vtkNew<vtkIdTypeArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, value);
  output->GetFieldData()->AddArray(a);
}
} // namespace

// What the steps of RequestData share during one execution.
struct vtkPsiConformingTetrahedralize::Execution
{
  explicit Execution(vtkDataSet* input)
    : Input(input)
    , UGrid(vtkUnstructuredGrid::SafeDownCast(input))
    , Points(InputPoints(input))
    , Coordinates(DoubleCoordinates(this->Points, input->GetNumberOfPoints()))
    , Tets(this->Coordinates.data())
  {
    StructuredDimensions(input, this->Dims);
    this->Structured3D = this->Dims[0] > 1 && this->Dims[1] > 1 && this->Dims[2] > 1;
  }

  vtkDataSet* Input;
  vtkUnstructuredGrid* UGrid; // the fast path to cell points and polyhedron faces
  int Dims[3];                // point dimensions of a structured grid, zeros otherwise
  bool Structured3D = false;  // cell (i, j, k) is the hexahedron computed from the indices
  bool FivePerHex = false;
  vtkSmartPointer<vtkPoints> Points;
  std::vector<double> Coordinates;
  psi::OrientedTetrahedra Tets;
  psi::FaceSet Faces;           // scratch: the faces of the current cell
  vtkNew<vtkIdList> FaceStream; // scratch: a polyhedron's face stream
  vtkNew<vtkIdList> CellPoints; // scratch: the points of the current cell
  bool WarnedUnsupported = false;
};

vtkPsiConformingTetrahedralize::vtkPsiConformingTetrahedralize() = default;
vtkPsiConformingTetrahedralize::~vtkPsiConformingTetrahedralize() = default;

int vtkPsiConformingTetrahedralize::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

int vtkPsiConformingTetrahedralize::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  this->NumberOfGeneratedTets = 0;
  this->NumberOfRemovedDegenerateTets = 0;
  this->NumberOfNonManifoldFaces = 0;
  this->NumberOfSkippedCells = 0;
  this->FellBackToConforming = false;
  output->Initialize();
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output data set.");
    return 0;
  }
  int result = 1;
  if (!this->CheckInput(input, result))
  {
    return result;
  }

  Execution exec(input);
  exec.FivePerHex = this->ChooseFivePerHex(exec);
  exec.Tets.Reserve(6 * static_cast<size_t>(input->GetNumberOfCells()));
  if (!this->SplitCells(exec))
  {
    output->Initialize();
    return 1;
  }
  this->NumberOfGeneratedTets = exec.Tets.Generated;
  this->NumberOfRemovedDegenerateTets = exec.Tets.Removed;
  if (!this->CheckTetrahedra(exec, result))
  {
    return result;
  }

  this->SetTetrahedra(exec, output);
  if (!this->CopyAttributes(exec, output))
  {
    output->Initialize();
    return 1;
  }
  this->AddFaceNeighbors(exec, output);
  this->AddCounts(input, output);
  if (this->NumberOfSkippedCells > 0)
  {
    vtkWarningMacro(<< this->NumberOfSkippedCells << " non-3D or unsupported cells were skipped.");
  }
  this->UpdateProgress(1.0);
  return 1;
}

bool vtkPsiConformingTetrahedralize::CheckInput(vtkDataSet* input, int& result)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (numCells == 0 || numPoints == 0)
  {
    vtkWarningMacro("The input is empty (" << numPoints << " points, " << numCells
                                           << " cells): the output is empty.");
    result = 1;
    return false;
  }
  if (numPoints >= static_cast<vtkIdType>(std::numeric_limits<uint32_t>::max()))
  {
    vtkErrorMacro("Too many points (" << numPoints << ") for 32-bit tetrahedron indices.");
    result = 0;
    return false;
  }
  return true;
}

bool vtkPsiConformingTetrahedralize::ChooseFivePerHex(const Execution& exec)
{
  if (this->SplitMode != FIVE_PER_HEX)
  {
    return false;
  }
  if (!exec.Structured3D)
  {
    this->FellBackToConforming = true;
    vtkWarningMacro("'Five per hex' conforms on structured 3D grids only (image, rectilinear, "
                    "structured); this "
      << exec.Input->GetClassName() << " is split by the conforming min-id rule instead.");
  }
  return exec.Structured3D;
}

bool vtkPsiConformingTetrahedralize::SplitCells(Execution& exec)
{
  const vtkIdType numCells = exec.Input->GetNumberOfCells();
  const vtkIdType progressStep = std::max<vtkIdType>(1, numCells / 100);
  const HiddenCells hidden(exec.Input);
  for (vtkIdType cellId = 0; cellId < numCells; ++cellId)
  {
    if (cellId % progressStep == 0)
    {
      this->UpdateProgress(0.8 * static_cast<double>(cellId) / numCells);
      if (this->CheckAbort())
      {
        return false;
      }
    }
    if (hidden(cellId))
    {
      continue;
    }
    if (exec.Structured3D)
    {
      this->SplitStructuredCell(exec, cellId);
    }
    else
    {
      this->SplitUnstructuredCell(exec, cellId);
    }
  }
  return true;
}

void vtkPsiConformingTetrahedralize::SplitStructuredCell(Execution& exec, vtkIdType cellId)
{
  vtkIdType hex[8];
  const vtkIdType ijkSum = psi::StructuredHexCorners(exec.Dims, cellId, hex);
  if (exec.FivePerHex)
  {
    psi::FivePerHexSplit(hex, ijkSum, cellId, exec.Tets);
    return;
  }
  this->SplitCell(exec, cellId, VTK_HEXAHEDRON, hex, 8);
}

void vtkPsiConformingTetrahedralize::SplitUnstructuredCell(Execution& exec, vtkIdType cellId)
{
  const int type = exec.Input->GetCellType(cellId);
  if (vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) != 3)
  {
    ++this->NumberOfSkippedCells;
    return;
  }
  const vtkIdType* pts = nullptr;
  vtkIdType npts = 0;
  if (exec.UGrid)
  {
    exec.UGrid->GetCellPoints(cellId, npts, pts, exec.CellPoints);
  }
  else
  {
    exec.Input->GetCellPoints(cellId, exec.CellPoints);
    npts = exec.CellPoints->GetNumberOfIds();
    pts = exec.CellPoints->GetPointer(0);
  }
  this->SplitCell(exec, cellId, type, pts, npts);
}

void vtkPsiConformingTetrahedralize::SplitCell(
  Execution& exec, vtkIdType cellId, int type, const vtkIdType* pts, vtkIdType npts)
{
  const int linearType = psi::LinearCellType(type);
  if (linearType == VTK_TETRA)
  {
    if (npts >= 4)
    {
      exec.Tets.Add(pts[0], pts[1], pts[2], pts[3], cellId);
    }
  }
  else if (psi::StandardCellFaces(linearType, pts, exec.Faces))
  {
    psi::ConeSplit(exec.Faces, cellId, exec.Tets);
  }
  else if (linearType == VTK_POLYHEDRON)
  {
    // Exact for convex polyhedra (see the header).
    if (!exec.UGrid)
    {
      ++this->NumberOfSkippedCells;
      return;
    }
    // The vtkIdList form (numFaces, numFace0Pts, ids..., numFace1Pts, ...) reads both face
    // storages: the legacy face stream of VTK 9.2 and the vtkCellArray faces of VTK 9.4+.
    exec.UGrid->GetFaceStream(cellId, exec.FaceStream);
    if (exec.FaceStream->GetNumberOfIds() < 1)
    {
      ++this->NumberOfSkippedCells;
      return;
    }
    vtkIdList* stream = exec.FaceStream;
    psi::PolyhedronFaces(
      stream->GetId(0), stream->GetPointer(1), stream->GetNumberOfIds() - 1, exec.Faces);
    psi::ConeSplit(exec.Faces, cellId, exec.Tets);
  }
  else
  {
    ++this->NumberOfSkippedCells;
    if (!exec.WarnedUnsupported)
    {
      exec.WarnedUnsupported = true;
      vtkWarningMacro("Cells of type " << vtkCellTypes::GetClassNameFromTypeId(type)
                                       << " are not tetrahedralized (skipped).");
    }
  }
}

bool vtkPsiConformingTetrahedralize::CheckTetrahedra(const Execution& exec, int& result)
{
  const vtkIdType numTets = static_cast<vtkIdType>(exec.Tets.Parent.size());
  if (numTets == 0)
  {
    if (exec.Tets.Generated == 0)
    {
      vtkWarningMacro("The input " << exec.Input->GetClassName() << " has no 3D cells ("
                                   << this->NumberOfSkippedCells
                                   << " cells skipped; a surface is not a volume): the output "
                                      "is empty.");
    }
    else
    {
      vtkWarningMacro("All " << exec.Tets.Generated
                             << " tetrahedra have zero volume (flat input): the output is empty.");
    }
    result = 1;
    return false;
  }
  if (numTets >= static_cast<vtkIdType>(std::numeric_limits<int32_t>::max()))
  {
    vtkErrorMacro("Too many tetrahedra (" << numTets << ") for 32-bit neighbour indices.");
    result = 0;
    return false;
  }
  return true;
}

void vtkPsiConformingTetrahedralize::SetTetrahedra(
  const Execution& exec, vtkUnstructuredGrid* output)
{
  const vtkIdType numTets = static_cast<vtkIdType>(exec.Tets.Parent.size());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numTets + 1);
  for (vtkIdType t = 0; t <= numTets; ++t)
  {
    offsets->SetValue(t, 4 * t);
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(4 * numTets);
  std::copy(
    exec.Tets.Connectivity.begin(), exec.Tets.Connectivity.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetPoints(exec.Points);
  output->SetCells(VTK_TETRA, cells);
  this->UpdateProgress(0.85);
}

bool vtkPsiConformingTetrahedralize::CopyAttributes(
  const Execution& exec, vtkUnstructuredGrid* output)
{
  // Point data unchanged, cell data to every child tetrahedron.
  const vtkIdType numTets = static_cast<vtkIdType>(exec.Tets.Parent.size());
  output->GetPointData()->PassData(exec.Input->GetPointData());
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(exec.Input->GetCellData(), numTets);
  vtkNew<vtkIdList> parents;
  parents->SetNumberOfIds(numTets);
  std::copy(exec.Tets.Parent.begin(), exec.Tets.Parent.end(), parents->GetPointer(0));
  outCD->CopyData(exec.Input->GetCellData(), parents.GetPointer(), static_cast<vtkIdType>(0));
  this->UpdateProgress(0.9);
  return !this->CheckAbort();
}

void vtkPsiConformingTetrahedralize::AddFaceNeighbors(
  const Execution& exec, vtkUnstructuredGrid* output)
{
  // Face adjacency, the input of MPVONC (Williams 1992; Maximo et al. 2010 §3.1).
  this->NumberOfNonManifoldFaces = static_cast<vtkIdType>(psi::AddFaceNeighborArrays(
    exec.Tets.Connectivity, exec.Input->GetNumberOfPoints(), output->GetCellData()));
}

void vtkPsiConformingTetrahedralize::AddCounts(vtkDataSet* input, vtkUnstructuredGrid* output)
{
  // Counts in field data, for the info property and for scripts.
  output->GetFieldData()->PassData(input->GetFieldData());
  AddCount(output, "RemovedDegenerateTets", this->NumberOfRemovedDegenerateTets);
  AddCount(output, "GeneratedTets", this->NumberOfGeneratedTets);
  AddCount(output, "NonManifoldFaces", this->NumberOfNonManifoldFaces);
}

void vtkPsiConformingTetrahedralize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SplitMode: " << (this->SplitMode == FIVE_PER_HEX ? "FivePerHex" : "Conforming")
     << "\n";
  os << indent << "NumberOfGeneratedTets: " << this->NumberOfGeneratedTets << "\n";
  os << indent << "NumberOfRemovedDegenerateTets: " << this->NumberOfRemovedDegenerateTets << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
  os << indent << "NumberOfSkippedCells: " << this->NumberOfSkippedCells << "\n";
}
