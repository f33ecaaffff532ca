#include "vtkPsiOFFTetReader.h"

#include "PsiOFFParser.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sys/stat.h>

vtkStandardNewMacro(vtkPsiOFFTetReader);

namespace
{
// Progress and abort are checked every this many data lines.
constexpr uint64_t ProgressStride = 1 << 16;
} // namespace

// The arrays of the mesh being read, and what the vertex and tetrahedron lines revealed.
struct vtkPsiOFFTetReader::Mesh
{
  vtkNew<vtkDoubleArray> Coords;
  vtkNew<vtkDoubleArray> Scalars;
  vtkNew<vtkIdTypeArray> Offsets;
  vtkNew<vtkIdTypeArray> Connectivity;
  vtkIdType NonFinitePoints = 0;
  vtkIdType NonFiniteScalars = 0;
  vtkIdType Degenerate = 0;
};

vtkPsiOFFTetReader::vtkPsiOFFTetReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPsiOFFTetReader::~vtkPsiOFFTetReader()
{
  this->SetFileName(nullptr);
}

void vtkPsiOFFTetReader::SetInputString(const char* data, size_t length)
{
  this->InputString.assign(data ? data : "", data ? length : 0);
  this->Modified();
}

void vtkPsiOFFTetReader::SetInputString(const std::string& s)
{
  this->SetInputString(s.data(), s.size());
}

int vtkPsiOFFTetReader::CanReadFile(const char* filename)
{
  return vtkPsiOFFTetReader::IsTetrahedralOFF(filename) ? 1 : 0;
}

bool vtkPsiOFFTetReader::IsTetrahedralOFF(const char* filename)
{
  if (!filename)
  {
    return false;
  }
  std::ifstream in(filename, std::ios::binary);
  if (!in)
  {
    return false;
  }
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  psi::OFFParser parser(head.data(), head.size());
  return parser.ReadHeader();
}

void vtkPsiOFFTetReader::Fail(unsigned long code, const std::string& message)
{
  this->LastError = message;
  this->SetErrorCode(code);
  const char* source = this->ReadFromInputString ? "input string" : this->FileName;
  vtkErrorMacro("Cannot read tetrahedral OFF " << (source ? source : "(null)") << ": " << message);
}

int vtkPsiOFFTetReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkPsiOFFTetReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outInfo);
  output->Initialize();
  this->LastError.clear();
  this->SetErrorCode(vtkErrorCode::NoError);
  this->NumberOfPointsRead = this->NumberOfTetrahedraRead = 0;
  this->NumberOfNonFinitePoints = this->NumberOfNonFiniteScalars = 0;
  this->NumberOfDegenerateTetrahedra = 0;

  // Piece 0 reads the whole mesh; the other pieces are empty.
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    return 1;
  }

  if (this->ReadFromInputString)
  {
    return this->Parse(this->InputString.data(), this->InputString.size(), output) ? 1 : 0;
  }
  std::string buffer;
  if (!this->LoadFile(buffer))
  {
    return 0;
  }
  return this->Parse(buffer.data(), buffer.size(), output) ? 1 : 0;
}

bool vtkPsiOFFTetReader::LoadFile(std::string& buffer)
{
  if (!this->FileName || !*this->FileName)
  {
    this->Fail(vtkErrorCode::NoFileNameError, "no file name given");
    return false;
  }
  struct stat st;
  if (stat(this->FileName, &st) != 0)
  {
    this->Fail(vtkErrorCode::FileNotFoundError, "no such file");
    return false;
  }
  if (!S_ISREG(st.st_mode))
  {
    this->Fail(vtkErrorCode::CannotOpenFileError, "not a regular file");
    return false;
  }
  std::ifstream in(this->FileName, std::ios::binary);
  if (!in)
  {
    this->Fail(vtkErrorCode::CannotOpenFileError, "the file cannot be opened");
    return false;
  }
  try
  {
    buffer.resize(static_cast<size_t>(st.st_size));
  }
  catch (const std::exception&)
  {
    this->Fail(vtkErrorCode::OutOfDiskSpaceError,
      "not enough memory to hold the file (" + std::to_string(st.st_size) + " bytes)");
    return false;
  }
  in.read(&buffer[0], static_cast<std::streamsize>(buffer.size()));
  buffer.resize(static_cast<size_t>(in.gcount()));
  return true;
}

bool vtkPsiOFFTetReader::Parse(const char* data, size_t size, vtkUnstructuredGrid* output)
{
  psi::OFFParser parser(data, size);
  if (!parser.ReadHeader() ||
    !parser.CheckCountsFitSize(static_cast<uint64_t>(std::numeric_limits<vtkIdType>::max() / 4)))
  {
    return this->FailParse(parser);
  }
  Mesh mesh;
  if (!this->AllocateMesh(parser, mesh) || !this->ReadVertices(parser, mesh) ||
    !this->ReadTetrahedra(parser, mesh))
  {
    return false;
  }
  if (!parser.ReadEnd())
  {
    return this->FailParse(parser);
  }
  this->StoreMesh(mesh, output);
  this->ReportMesh(parser, mesh);
  this->UpdateProgress(1.0);
  return true;
}

bool vtkPsiOFFTetReader::FailParse(const psi::OFFParser& parser)
{
  this->Fail(parser.GetErrorKind() == psi::OFFParser::ErrorKind::Truncated
      ? vtkErrorCode::PrematureEndOfFileError
      : vtkErrorCode::FileFormatError,
    parser.GetErrorMessage());
  return false;
}

bool vtkPsiOFFTetReader::AllocateMesh(const psi::OFFParser& parser, Mesh& mesh)
{
  const uint64_t nverts = parser.GetNumberOfVertices();
  const uint64_t ntets = parser.GetNumberOfTetrahedra();
  mesh.Coords->SetNumberOfComponents(3);
  mesh.Scalars->SetName("scalars");
  try
  {
    mesh.Coords->SetNumberOfTuples(static_cast<vtkIdType>(nverts));
    mesh.Scalars->SetNumberOfTuples(static_cast<vtkIdType>(nverts));
    mesh.Offsets->SetNumberOfTuples(static_cast<vtkIdType>(ntets + 1));
    mesh.Connectivity->SetNumberOfTuples(static_cast<vtkIdType>(4 * ntets));
  }
  catch (const std::exception&)
  {
    this->Fail(vtkErrorCode::OutOfDiskSpaceError, "not enough memory for the mesh");
    return false;
  }
  if ((nverts && !mesh.Coords->GetPointer(0)) || !mesh.Offsets->GetPointer(0) ||
    (ntets && !mesh.Connectivity->GetPointer(0)))
  {
    this->Fail(vtkErrorCode::OutOfDiskSpaceError, "not enough memory for the mesh");
    return false;
  }
  return true;
}

bool vtkPsiOFFTetReader::Progress(uint64_t done, uint64_t total)
{
  if (done % ProgressStride == 0 && total > ProgressStride)
  {
    this->UpdateProgress(static_cast<double>(done) / static_cast<double>(total));
    if (this->GetAbortExecute())
    {
      this->Fail(vtkErrorCode::UserError, "reading was aborted");
      return false;
    }
  }
  return true;
}

bool vtkPsiOFFTetReader::ReadVertices(psi::OFFParser& parser, Mesh& mesh)
{
  const uint64_t nverts = parser.GetNumberOfVertices();
  const uint64_t totalLines = nverts + parser.GetNumberOfTetrahedra();
  double* xyz = mesh.Coords->GetPointer(0);
  double* s = mesh.Scalars->GetPointer(0);
  for (uint64_t i = 0; i < nverts; ++i)
  {
    if (!this->Progress(i, totalLines))
    {
      return false;
    }
    double v[4];
    if (!parser.ReadVertex(i, v))
    {
      return this->FailParse(parser);
    }
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    {
      ++mesh.NonFinitePoints;
    }
    if (!std::isfinite(v[3]))
    {
      ++mesh.NonFiniteScalars;
    }
    xyz[3 * i] = v[0];
    xyz[3 * i + 1] = v[1];
    xyz[3 * i + 2] = v[2];
    s[i] = v[3];
  }
  return true;
}

bool vtkPsiOFFTetReader::ReadTetrahedra(psi::OFFParser& parser, Mesh& mesh)
{
  const uint64_t nverts = parser.GetNumberOfVertices();
  const uint64_t ntets = parser.GetNumberOfTetrahedra();
  vtkIdType* conn = mesh.Connectivity->GetPointer(0);
  vtkIdType* off = mesh.Offsets->GetPointer(0);
  off[0] = 0;
  for (uint64_t t = 0; t < ntets; ++t)
  {
    if (!this->Progress(nverts + t, nverts + ntets))
    {
      return false;
    }
    uint64_t read[4];
    if (!parser.ReadTetrahedron(t, read))
    {
      return this->FailParse(parser);
    }
    vtkIdType* ids = conn + 4 * t;
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = static_cast<vtkIdType>(read[k]);
    }
    if (ids[0] == ids[1] || ids[0] == ids[2] || ids[0] == ids[3] || ids[1] == ids[2] ||
      ids[1] == ids[3] || ids[2] == ids[3])
    {
      ++mesh.Degenerate;
    }
    off[t + 1] = static_cast<vtkIdType>(4 * (t + 1));
  }
  return true;
}

void vtkPsiOFFTetReader::StoreMesh(Mesh& mesh, vtkUnstructuredGrid* output)
{
  vtkNew<vtkPoints> points;
  points->SetData(mesh.Coords);
  vtkNew<vtkCellArray> cells;
  cells->SetData(mesh.Offsets, mesh.Connectivity);
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  output->GetPointData()->SetScalars(mesh.Scalars);
}

void vtkPsiOFFTetReader::ReportMesh(const psi::OFFParser& parser, const Mesh& mesh)
{
  const uint64_t nverts = parser.GetNumberOfVertices();
  const uint64_t ntets = parser.GetNumberOfTetrahedra();
  this->NumberOfPointsRead = static_cast<vtkIdType>(nverts);
  this->NumberOfTetrahedraRead = static_cast<vtkIdType>(ntets);
  this->NumberOfNonFinitePoints = mesh.NonFinitePoints;
  this->NumberOfNonFiniteScalars = mesh.NonFiniteScalars;
  this->NumberOfDegenerateTetrahedra = mesh.Degenerate;
  if (mesh.NonFinitePoints)
  {
    vtkWarningMacro(<< mesh.NonFinitePoints << " of the " << nverts
                    << " vertices have a NaN or infinite coordinate (kept as read).");
  }
  if (mesh.NonFiniteScalars)
  {
    vtkWarningMacro(<< mesh.NonFiniteScalars << " of the " << nverts
                    << " vertices have a NaN or infinite scalar (kept as read; 'Psi Volume' skips "
                       "the tetrahedra that use them).");
  }
  if (mesh.Degenerate)
  {
    vtkWarningMacro(<< mesh.Degenerate << " of the " << ntets
                    << " tetrahedra repeat a vertex (zero volume; kept as read).");
  }
  if (ntets == 0)
  {
    vtkWarningMacro("The mesh has no tetrahedra.");
  }
}

void vtkPsiOFFTetReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReadFromInputString: " << this->ReadFromInputString << "\n";
  os << indent << "InputString: " << this->InputString.size() << " bytes\n";
  os << indent << "LastError: " << this->LastError << "\n";
  os << indent << "NumberOfPointsRead: " << this->NumberOfPointsRead << "\n";
  os << indent << "NumberOfTetrahedraRead: " << this->NumberOfTetrahedraRead << "\n";
  os << indent << "NumberOfNonFinitePoints: " << this->NumberOfNonFinitePoints << "\n";
  os << indent << "NumberOfNonFiniteScalars: " << this->NumberOfNonFiniteScalars << "\n";
  os << indent << "NumberOfDegenerateTetrahedra: " << this->NumberOfDegenerateTetrahedra << "\n";
}
