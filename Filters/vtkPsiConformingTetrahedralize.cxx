#include "vtkPsiConformingTetrahedralize.h"

#include "PsiTetConnectivity.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkHexagonalPrism.h"
#include "vtkHexahedron.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPentagonalPrism.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPyramid.h"
#include "vtkRectilinearGrid.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkWedge.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkPsiConformingTetrahedralize);

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;

// The literature's 5-tetrahedra split of a hexahedron (VTK corner order), in its two mirror
// images; alternating them with the parity of i + j + k makes the face diagonals of structured
// neighbours coincide (even: diagonals 0-2, 0-5, 0-7, 2-5, 2-7, 5-7; odd: the other ones).
constexpr int FiveEven[5][4] = { { 1, 0, 2, 5 }, { 3, 0, 2, 7 }, { 4, 0, 5, 7 }, { 6, 2, 5, 7 },
  { 0, 2, 5, 7 } };
constexpr int FiveOdd[5][4] = { { 0, 1, 3, 4 }, { 2, 1, 3, 6 }, { 5, 1, 4, 6 }, { 7, 3, 4, 6 },
  { 1, 3, 4, 6 } };

// A cell given by its faces (polygons of global point ids, cyclic order).
struct FaceSet
{
  std::vector<vtkIdType> Ids;     // all face ids, concatenated
  std::vector<vtkIdType> Offsets; // start of each face in Ids, plus the end
  void Clear()
  {
    this->Ids.clear();
    this->Offsets.assign(1, 0);
  }
  void Close() { this->Offsets.push_back(static_cast<vtkIdType>(this->Ids.size())); }
};

// Adds the faces of a standard linear cell from VTK's static face tables (local ids, -1 ends a
// face shorter than MaximumFaceSize).
template <class CellT>
void AddStandardFaces(const vtkIdType* pts, FaceSet& faces)
{
  faces.Clear();
  for (vtkIdType f = 0; f < CellT::NumberOfFaces; ++f)
  {
    const vtkIdType* local = CellT::GetFaceArray(f);
    for (vtkIdType k = 0; k < CellT::MaximumFaceSize && local[k] >= 0; ++k)
    {
      faces.Ids.push_back(pts[local[k]]);
    }
    faces.Close();
  }
}

// The point ids of the linear cell under a higher-order one (its corners come first in VTK's
// ordering), or VTK_EMPTY_CELL when the type is not handled.
int LinearType(int type)
{
  switch (type)
  {
    case VTK_TETRA:
    case VTK_QUADRATIC_TETRA:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_BEZIER_TETRAHEDRON:
    case VTK_HIGHER_ORDER_TETRAHEDRON:
      return VTK_TETRA;
    case VTK_HEXAHEDRON:
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON:
    case VTK_BEZIER_HEXAHEDRON:
    case VTK_HIGHER_ORDER_HEXAHEDRON:
      return VTK_HEXAHEDRON;
    case VTK_WEDGE:
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_LAGRANGE_WEDGE:
    case VTK_BEZIER_WEDGE:
    case VTK_HIGHER_ORDER_WEDGE:
      return VTK_WEDGE;
    case VTK_PYRAMID:
    case VTK_QUADRATIC_PYRAMID:
    case VTK_TRIQUADRATIC_PYRAMID:
    case VTK_LAGRANGE_PYRAMID:
    case VTK_BEZIER_PYRAMID:
    case VTK_HIGHER_ORDER_PYRAMID:
      return VTK_PYRAMID;
    case VTK_VOXEL:
    case VTK_PENTAGONAL_PRISM:
    case VTK_HEXAGONAL_PRISM:
    case VTK_POLYHEDRON:
      return type;
    default:
      return VTK_EMPTY_CELL;
  }
}

// Collects tetrahedra: orients them positively with CGAL's exact orientation predicate and drops
// the flat ones (CGAL::COPLANAR).
struct TetSink
{
  const std::vector<Point3>& Points;
  std::vector<vtkIdType> Connectivity;
  std::vector<vtkIdType> Parent;
  vtkIdType Generated = 0;
  vtkIdType Removed = 0;

  explicit TetSink(const std::vector<Point3>& points)
    : Points(points)
  {
  }

  void Add(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d, vtkIdType cellId)
  {
    ++this->Generated;
    switch (CGAL::orientation(this->Points[a], this->Points[b], this->Points[c], this->Points[d]))
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

  // The conforming split: every face is triangulated by the fan from its smallest id (a quad by
  // its min-id diagonal) and the cell is the cone from its smallest id over the faces that do
  // not contain it. The faces that do contain it are fans from it, i.e. the same rule, so both
  // cells sharing a face triangulate it identically whatever the cell types.
  void ConeSplit(const FaceSet& faces, vtkIdType cellId)
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
        this->Add(apex, p[k], p[(k + j) % n], p[(k + j + 1) % n], cellId);
      }
    }
  }
};
} // namespace

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
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (numCells == 0 || numPoints == 0)
  {
    vtkWarningMacro("The input is empty (" << numPoints << " points, " << numCells
                                           << " cells): the output is empty.");
    return 1;
  }
  if (numPoints >= static_cast<vtkIdType>(std::numeric_limits<uint32_t>::max()))
  {
    vtkErrorMacro("Too many points (" << numPoints << ") for 32-bit tetrahedron indices.");
    return 0;
  }

  // Structured input: cell (i, j, k) has the hexahedron corners computed from the indices.
  int dims[3] = { 0, 0, 0 };
  vtkStructuredGrid* sgrid = vtkStructuredGrid::SafeDownCast(input);
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    image->GetDimensions(dims);
  }
  else if (auto* rgrid = vtkRectilinearGrid::SafeDownCast(input))
  {
    rgrid->GetDimensions(dims);
  }
  else if (sgrid)
  {
    sgrid->GetDimensions(dims);
  }
  const bool structured3D = dims[0] > 1 && dims[1] > 1 && dims[2] > 1;
  const bool fiveSplit = this->SplitMode == FIVE_PER_HEX && structured3D;
  if (this->SplitMode == FIVE_PER_HEX && !structured3D)
  {
    this->FellBackToConforming = true;
    vtkWarningMacro("'Five per hex' conforms on structured 3D grids only (image, rectilinear, "
                    "structured); this "
      << input->GetClassName() << " is split by the conforming min-id rule instead.");
  }

  // Points: shared with a point set, generated for implicit grids.
  vtkSmartPointer<vtkPoints> points;
  if (auto* ps = vtkPointSet::SafeDownCast(input))
  {
    points = ps->GetPoints();
  }
  if (!points)
  {
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
  std::vector<Point3> cgalPoints(numPoints);
  vtkSMPTools::For(0, numPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      double x[3];
      points->GetPoint(i, x);
      cgalPoints[i] = Point3(x[0], x[1], x[2]);
    }
  });

  // Hidden (blanked) cells are skipped: IBLANK of PLOT3D grids, for instance.
  const bool sgridBlanking = sgrid && (sgrid->HasAnyBlankCells() || sgrid->HasAnyBlankPoints());
  vtkUnsignedCharArray* cellGhosts = input->GetCellData()->GetGhostArray();
  auto hidden = [&](vtkIdType cellId) {
    if (sgridBlanking)
    {
      return !sgrid->IsCellVisible(cellId);
    }
    return cellGhosts && (cellGhosts->GetValue(cellId) & vtkDataSetAttributes::HIDDENCELL);
  };

  TetSink sink(cgalPoints);
  sink.Connectivity.reserve(4 * 6 * static_cast<size_t>(numCells));
  sink.Parent.reserve(6 * static_cast<size_t>(numCells));
  FaceSet faces;
  vtkNew<vtkIdList> cellPoints;
  const vtkIdType progressStep = std::max<vtkIdType>(1, numCells / 100);
  bool aborted = false;
  vtkUnstructuredGrid* ugrid = vtkUnstructuredGrid::SafeDownCast(input);
  bool warnedUnsupported = false;

  for (vtkIdType cellId = 0; cellId < numCells && !aborted; ++cellId)
  {
    if (cellId % progressStep == 0)
    {
      this->UpdateProgress(0.8 * static_cast<double>(cellId) / numCells);
      if (this->CheckAbort())
      {
        aborted = true;
        break;
      }
    }
    if (hidden(cellId))
    {
      continue;
    }
    vtkIdType hex[8];
    const vtkIdType* pts = nullptr;
    vtkIdType npts = 0;
    int type;
    if (structured3D)
    {
      const vtkIdType cx = dims[0] - 1, cy = dims[1] - 1;
      const vtkIdType i = cellId % cx, j = (cellId / cx) % cy, k = cellId / (cx * cy);
      const vtkIdType nx = dims[0], nxy = static_cast<vtkIdType>(dims[0]) * dims[1];
      const vtkIdType base = i + j * nx + k * nxy;
      hex[0] = base;
      hex[1] = base + 1;
      hex[2] = base + 1 + nx;
      hex[3] = base + nx;
      for (int c = 0; c < 4; ++c)
      {
        hex[c + 4] = hex[c] + nxy;
      }
      if (fiveSplit)
      {
        const auto& split = ((i + j + k) % 2 == 0) ? FiveEven : FiveOdd;
        for (const auto& t : split)
        {
          sink.Add(hex[t[0]], hex[t[1]], hex[t[2]], hex[t[3]], cellId);
        }
        continue;
      }
      pts = hex;
      npts = 8;
      type = VTK_HEXAHEDRON;
    }
    else
    {
      type = input->GetCellType(cellId);
      if (vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) != 3)
      {
        ++this->NumberOfSkippedCells;
        continue;
      }
      if (ugrid)
      {
        ugrid->GetCellPoints(cellId, npts, pts, cellPoints);
      }
      else
      {
        input->GetCellPoints(cellId, cellPoints);
        npts = cellPoints->GetNumberOfIds();
        pts = cellPoints->GetPointer(0);
      }
    }

    switch (LinearType(type))
    {
      case VTK_TETRA:
        if (npts >= 4)
        {
          sink.Add(pts[0], pts[1], pts[2], pts[3], cellId);
        }
        break;
      case VTK_HEXAHEDRON:
        AddStandardFaces<vtkHexahedron>(pts, faces);
        sink.ConeSplit(faces, cellId);
        break;
      case VTK_VOXEL:
      {
        // Voxel corners in hexahedron order (VTK's voxel face table is not cyclic).
        const vtkIdType h[8] = { pts[0], pts[1], pts[3], pts[2], pts[4], pts[5], pts[7], pts[6] };
        AddStandardFaces<vtkHexahedron>(h, faces);
        sink.ConeSplit(faces, cellId);
        break;
      }
      case VTK_WEDGE:
        AddStandardFaces<vtkWedge>(pts, faces);
        sink.ConeSplit(faces, cellId);
        break;
      case VTK_PYRAMID:
        AddStandardFaces<vtkPyramid>(pts, faces);
        sink.ConeSplit(faces, cellId);
        break;
      case VTK_PENTAGONAL_PRISM:
        AddStandardFaces<vtkPentagonalPrism>(pts, faces);
        sink.ConeSplit(faces, cellId);
        break;
      case VTK_HEXAGONAL_PRISM:
        AddStandardFaces<vtkHexagonalPrism>(pts, faces);
        sink.ConeSplit(faces, cellId);
        break;
      case VTK_POLYHEDRON:
      {
        // Face stream: nfaces x (npts, ids...). Exact for convex polyhedra (see the header).
        vtkIdType nfaces = 0;
        const vtkIdType* stream = nullptr;
        if (!ugrid)
        {
          ++this->NumberOfSkippedCells;
          break;
        }
        ugrid->GetFaceStream(cellId, nfaces, stream);
        faces.Clear();
        for (vtkIdType f = 0; f < nfaces && stream; ++f)
        {
          const vtkIdType n = *stream++;
          faces.Ids.insert(faces.Ids.end(), stream, stream + n);
          stream += n;
          faces.Close();
        }
        sink.ConeSplit(faces, cellId);
        break;
      }
      default:
        ++this->NumberOfSkippedCells;
        if (!warnedUnsupported)
        {
          warnedUnsupported = true;
          vtkWarningMacro("Cells of type " << vtkCellTypes::GetClassNameFromTypeId(type)
                                           << " are not tetrahedralized (skipped).");
        }
        break;
    }
  }
  if (aborted)
  {
    output->Initialize();
    return 1;
  }

  this->NumberOfGeneratedTets = sink.Generated;
  this->NumberOfRemovedDegenerateTets = sink.Removed;
  const vtkIdType numTets = static_cast<vtkIdType>(sink.Parent.size());
  if (numTets == 0)
  {
    if (sink.Generated == 0)
    {
      vtkWarningMacro("The input " << input->GetClassName() << " has no 3D cells ("
                                   << this->NumberOfSkippedCells
                                   << " cells skipped; a surface is not a volume): the output "
                                      "is empty.");
    }
    else
    {
      vtkWarningMacro("All " << sink.Generated
                             << " tetrahedra have zero volume (flat input): the output is empty.");
    }
    return 1;
  }
  if (numTets >= static_cast<vtkIdType>(std::numeric_limits<int32_t>::max()))
  {
    vtkErrorMacro("Too many tetrahedra (" << numTets << ") for 32-bit neighbour indices.");
    return 0;
  }

  // Cells.
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numTets + 1);
  for (vtkIdType t = 0; t <= numTets; ++t)
  {
    offsets->SetValue(t, 4 * t);
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(4 * numTets);
  std::copy(sink.Connectivity.begin(), sink.Connectivity.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  this->UpdateProgress(0.85);

  // Attributes: point data unchanged, cell data to every child tetrahedron.
  output->GetPointData()->PassData(input->GetPointData());
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(input->GetCellData(), numTets);
  {
    vtkNew<vtkIdList> parents;
    parents->SetNumberOfIds(numTets);
    std::copy(sink.Parent.begin(), sink.Parent.end(), parents->GetPointer(0));
    outCD->CopyData(input->GetCellData(), parents.GetPointer(), static_cast<vtkIdType>(0));
  }
  this->UpdateProgress(0.9);
  if (this->CheckAbort())
  {
    output->Initialize();
    return 1;
  }

  // Face adjacency (psi::ComputeTetNeighbors), the input of MPVONC (seed 002 §3.1).
  std::vector<uint32_t> tets32(sink.Connectivity.begin(), sink.Connectivity.end());
  std::vector<int32_t> neighbors;
  const psi::TetConnectivityResult conn = psi::ComputeTetNeighbors(
    tets32.data(), static_cast<size_t>(numTets), static_cast<size_t>(numPoints), neighbors);
  this->NumberOfNonManifoldFaces = static_cast<vtkIdType>(conn.NonManifoldFaces);
  vtkNew<vtkIntArray> faceNeighbors;
  faceNeighbors->SetName("FaceNeighbors");
  faceNeighbors->SetNumberOfComponents(4);
  faceNeighbors->SetNumberOfTuples(numTets);
  std::copy(neighbors.begin(), neighbors.end(), faceNeighbors->GetPointer(0));
  outCD->AddArray(faceNeighbors);
  const std::vector<uint8_t> flags = psi::BoundaryFaceFlags(neighbors);
  vtkNew<vtkUnsignedCharArray> boundary;
  boundary->SetName("BoundaryFaces");
  boundary->SetNumberOfTuples(numTets);
  std::copy(flags.begin(), flags.end(), boundary->GetPointer(0));
  outCD->AddArray(boundary);

  // Counts in field data, for the info property and for scripts.
  output->GetFieldData()->PassData(input->GetFieldData());
  auto addCount = [&](const char* name, vtkIdType value) {
    vtkNew<vtkIdTypeArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(1);
    a->SetValue(0, value);
    output->GetFieldData()->AddArray(a);
  };
  addCount("RemovedDegenerateTets", this->NumberOfRemovedDegenerateTets);
  addCount("GeneratedTets", this->NumberOfGeneratedTets);
  addCount("NonManifoldFaces", this->NumberOfNonManifoldFaces);
  if (this->NumberOfSkippedCells > 0)
  {
    vtkWarningMacro(<< this->NumberOfSkippedCells << " non-3D or unsupported cells were skipped.");
  }
  this->UpdateProgress(1.0);
  return 1;
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
