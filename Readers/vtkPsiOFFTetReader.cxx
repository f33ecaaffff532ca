#include "vtkPsiOFFTetReader.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <sys/stat.h>
#include <system_error>

vtkStandardNewMacro(vtkPsiOFFTetReader);

namespace
{
// The shortest possible data line is "0 0 0 0\n": 8 bytes (the last line may lack its '\n').
constexpr uint64_t MinBytesPerLine = 8;
// Progress and abort are checked every this many data lines.
constexpr uint64_t ProgressStride = 1 << 16;

inline bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

struct Token
{
  const char* Begin;
  const char* End;
  // The token for a message: at most 40 bytes, non-printable bytes escaped as \xNN.
  std::string Text() const
  {
    static const char* const hex = "0123456789abcdef";
    std::string out;
    const size_t n = std::min<size_t>(static_cast<size_t>(End - Begin), 40);
    for (size_t i = 0; i < n; ++i)
    {
      const unsigned char c = static_cast<unsigned char>(Begin[i]);
      if (c >= 0x20 && c < 0x7f)
      {
        out += static_cast<char>(c);
      }
      else
      {
        out += "\\x";
        out += hex[c >> 4];
        out += hex[c & 15];
      }
    }
    if (static_cast<size_t>(End - Begin) > n)
    {
      out += "...";
    }
    return out;
  }
};

// Lines of a byte buffer, numbered from 1; blank lines and '#' comment lines are skipped.
class LineCursor
{
public:
  LineCursor(const char* data, size_t size)
    : P(data)
    , End(data + size)
  {
    // A UTF-8 byte-order mark is not part of the content.
    if (size >= 3 && std::memcmp(data, "\xEF\xBB\xBF", 3) == 0)
    {
      this->P += 3;
    }
  }

  // The next line with content; false at the end of the buffer.
  bool NextContentLine(const char*& begin, const char*& end)
  {
    while (this->P < this->End)
    {
      const char* nl = static_cast<const char*>(std::memchr(this->P, '\n', this->End - this->P));
      begin = this->P;
      end = nl ? nl : this->End;
      this->P = nl ? nl + 1 : this->End;
      ++this->Line;
      const char* q = begin;
      while (q < end && IsSpace(*q))
      {
        ++q;
      }
      if (q == end || *q == '#')
      {
        continue;
      }
      return true;
    }
    return false;
  }

  size_t Remaining() const { return static_cast<size_t>(this->End - this->P); }
  uint64_t Line = 0;

private:
  const char* P;
  const char* End;
};

// Splits [begin, end) at whitespace into at most maxTokens tokens; returns the number of tokens
// found, which is maxTokens + 1 when there are more.
int Tokenize(const char* begin, const char* end, Token* tokens, int maxTokens)
{
  int n = 0;
  const char* p = begin;
  while (true)
  {
    while (p < end && IsSpace(*p))
    {
      ++p;
    }
    if (p == end)
    {
      return n;
    }
    if (n == maxTokens)
    {
      return n + 1;
    }
    const char* s = p;
    while (p < end && !IsSpace(*p))
    {
      ++p;
    }
    tokens[n++] = Token{ s, p };
  }
}

enum class NumberStatus
{
  Ok,
  NotANumber,
  OutOfRange
};

NumberStatus ParseDouble(const Token& t, double& value)
{
  const char* b = t.Begin;
  if (b < t.End && *b == '+')
  {
    ++b; // from_chars does not take a leading '+'
    if (b < t.End && (*b == '-' || *b == '+'))
    {
      return NumberStatus::NotANumber;
    }
  }
  const auto r = std::from_chars(b, t.End, value, std::chars_format::general);
  if (r.ec == std::errc::result_out_of_range && r.ptr == t.End)
  {
    return NumberStatus::OutOfRange;
  }
  if (r.ec != std::errc() || r.ptr != t.End)
  {
    return NumberStatus::NotANumber;
  }
  return NumberStatus::Ok;
}

// A non-negative decimal integer (an optional leading '+' is accepted).
NumberStatus ParseCount(const Token& t, uint64_t& value)
{
  const char* b = t.Begin;
  if (b < t.End && *b == '+')
  {
    ++b;
  }
  if (b == t.End || *b < '0' || *b > '9')
  {
    return NumberStatus::NotANumber;
  }
  const auto r = std::from_chars(b, t.End, value, 10);
  if (r.ec == std::errc::result_out_of_range)
  {
    return NumberStatus::OutOfRange;
  }
  if (r.ec != std::errc() || r.ptr != t.End)
  {
    return NumberStatus::NotANumber;
  }
  return NumberStatus::Ok;
}

bool IsOFFKeyword(const Token& t)
{
  return t.End - t.Begin == 3 && (t.Begin[0] == 'O' || t.Begin[0] == 'o') &&
    (t.Begin[1] == 'F' || t.Begin[1] == 'f') && (t.Begin[2] == 'F' || t.Begin[2] == 'f');
}

// The header: optional "OFF" keyword, then exactly two counts. On failure `error` says why.
bool ParseHeader(LineCursor& cur, uint64_t& nverts, uint64_t& ntets, std::string& error)
{
  const char *b, *e;
  if (!cur.NextContentLine(b, e))
  {
    error = "the file is empty (no 'nverts ntets' header)";
    return false;
  }
  Token tok[4];
  int n = Tokenize(b, e, tok, 4);
  int first = 0;
  if (n >= 1 && IsOFFKeyword(tok[0]))
  {
    first = 1;
    if (n == 1)
    {
      if (!cur.NextContentLine(b, e))
      {
        error = "the file ends after its 'OFF' keyword (no 'nverts ntets' counts)";
        return false;
      }
      n = Tokenize(b, e, tok, 4);
      first = 0;
    }
  }
  const int counts = n - first; // n == 5 means "more than 4 tokens"
  std::ostringstream msg;
  msg << "line " << cur.Line << ": ";
  uint64_t a;
  if (counts >= 3 && ParseCount(tok[first], a) == NumberStatus::Ok)
  {
    msg << "the header has three or more counts: this looks like a polygonal OFF surface "
           "('nverts nfaces nedges'), not a tetrahedral mesh ('nverts ntets')";
    error = msg.str();
    return false;
  }
  if (counts != 2)
  {
    msg << "expected the header 'nverts ntets' (two non-negative integers), found "
        << (counts >= 3 ? std::string("3 or more values") : std::to_string(counts) + " value(s)");
    if (counts >= 1)
    {
      msg << " starting with '" << tok[first].Text() << "'";
    }
    error = msg.str();
    return false;
  }
  uint64_t* out[2] = { &nverts, &ntets };
  const char* what[2] = { "vertex count", "tetrahedron count" };
  for (int k = 0; k < 2; ++k)
  {
    const NumberStatus s = ParseCount(tok[first + k], *out[k]);
    if (s != NumberStatus::Ok)
    {
      msg << "the " << what[k] << " '" << tok[first + k].Text() << "' "
          << (s == NumberStatus::OutOfRange ? "is absurdly large"
                                            : "is not a non-negative integer");
      error = msg.str();
      return false;
    }
  }
  return true;
}

// Whether the remaining bytes can hold the declared lines (no allocation happens before this).
bool CountsFitSize(uint64_t nverts, uint64_t ntets, size_t remaining, std::string& error)
{
  const uint64_t lines = nverts + ntets; // both are < 2^64 / 2 here or the checks below fail
  const bool fits = nverts <= remaining && ntets <= remaining &&
    lines * MinBytesPerLine <= static_cast<uint64_t>(remaining) + 1 &&
    nverts <= static_cast<uint64_t>(std::numeric_limits<vtkIdType>::max() / 4) &&
    ntets <= static_cast<uint64_t>(std::numeric_limits<vtkIdType>::max() / 4);
  if (!fits)
  {
    std::ostringstream msg;
    msg << "the header declares " << nverts << " vertices and " << ntets
        << " tetrahedra, which need at least " << MinBytesPerLine << " bytes per line, but only "
        << remaining
        << " bytes follow the header: the counts are wrong or the file is truncated";
    error = msg.str();
  }
  return fits;
}
} // namespace

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
  if (!filename)
  {
    return 0;
  }
  std::ifstream in(filename, std::ios::binary);
  if (!in)
  {
    return 0;
  }
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  LineCursor cur(head.data(), head.size());
  uint64_t nv = 0, nt = 0;
  std::string error;
  return ParseHeader(cur, nv, nt, error) ? 1 : 0;
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
  if (!this->FileName || !*this->FileName)
  {
    this->Fail(vtkErrorCode::NoFileNameError, "no file name given");
    return 0;
  }
  struct stat st;
  if (stat(this->FileName, &st) != 0)
  {
    this->Fail(vtkErrorCode::FileNotFoundError, "no such file");
    return 0;
  }
  if (!S_ISREG(st.st_mode))
  {
    this->Fail(vtkErrorCode::CannotOpenFileError, "not a regular file");
    return 0;
  }
  std::ifstream in(this->FileName, std::ios::binary);
  if (!in)
  {
    this->Fail(vtkErrorCode::CannotOpenFileError, "the file cannot be opened");
    return 0;
  }
  std::string buffer;
  try
  {
    buffer.resize(static_cast<size_t>(st.st_size));
  }
  catch (const std::exception&)
  {
    this->Fail(vtkErrorCode::OutOfDiskSpaceError,
      "not enough memory to hold the file (" + std::to_string(st.st_size) + " bytes)");
    return 0;
  }
  in.read(&buffer[0], static_cast<std::streamsize>(buffer.size()));
  buffer.resize(static_cast<size_t>(in.gcount()));
  return this->Parse(buffer.data(), buffer.size(), output) ? 1 : 0;
}

bool vtkPsiOFFTetReader::Parse(const char* data, size_t size, vtkUnstructuredGrid* output)
{
  LineCursor cur(data, size);
  uint64_t nverts = 0, ntets = 0;
  std::string error;
  if (!ParseHeader(cur, nverts, ntets, error))
  {
    this->Fail(vtkErrorCode::FileFormatError, error);
    return false;
  }
  if (!CountsFitSize(nverts, ntets, cur.Remaining(), error))
  {
    this->Fail(vtkErrorCode::PrematureEndOfFileError, error);
    return false;
  }

  vtkNew<vtkDoubleArray> coords;
  coords->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("scalars");
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  try
  {
    coords->SetNumberOfTuples(static_cast<vtkIdType>(nverts));
    scalars->SetNumberOfTuples(static_cast<vtkIdType>(nverts));
    offsets->SetNumberOfTuples(static_cast<vtkIdType>(ntets + 1));
    connectivity->SetNumberOfTuples(static_cast<vtkIdType>(4 * ntets));
  }
  catch (const std::exception&)
  {
    this->Fail(vtkErrorCode::OutOfDiskSpaceError, "not enough memory for the mesh");
    return false;
  }
  if ((nverts && !coords->GetPointer(0)) || !offsets->GetPointer(0) ||
    (ntets && !connectivity->GetPointer(0)))
  {
    this->Fail(vtkErrorCode::OutOfDiskSpaceError, "not enough memory for the mesh");
    return false;
  }

  const uint64_t totalLines = nverts + ntets;
  auto progress = [&](uint64_t done) -> bool {
    if (done % ProgressStride == 0 && totalLines > ProgressStride)
    {
      this->UpdateProgress(static_cast<double>(done) / static_cast<double>(totalLines));
      if (this->GetAbortExecute())
      {
        this->Fail(vtkErrorCode::UserError, "reading was aborted");
        return false;
      }
    }
    return true;
  };

  const char *b, *e;
  Token tok[5];
  double* xyz = coords->GetPointer(0);
  double* s = scalars->GetPointer(0);
  vtkIdType nonFinitePoints = 0, nonFiniteScalars = 0;
  static const char* const vertexField[4] = { "x", "y", "z", "s" };
  for (uint64_t i = 0; i < nverts; ++i)
  {
    if (!progress(i))
    {
      return false;
    }
    if (!cur.NextContentLine(b, e))
    {
      std::ostringstream msg;
      msg << "the file ends after " << i << " of the " << nverts
          << " vertices declared by the header (truncated, or the counts are wrong)";
      this->Fail(vtkErrorCode::PrematureEndOfFileError, msg.str());
      return false;
    }
    const int n = Tokenize(b, e, tok, 4);
    if (n != 4)
    {
      std::ostringstream msg;
      msg << "line " << cur.Line << ": vertex " << i << " needs 4 values 'x y z s', found "
          << (n > 4 ? std::string("more") : std::to_string(n))
          << " (the counts may not match the file)";
      this->Fail(vtkErrorCode::FileFormatError, msg.str());
      return false;
    }
    double v[4];
    for (int k = 0; k < 4; ++k)
    {
      const NumberStatus st = ParseDouble(tok[k], v[k]);
      if (st != NumberStatus::Ok)
      {
        std::ostringstream msg;
        msg << "line " << cur.Line << ": " << vertexField[k] << " of vertex " << i << " '"
            << tok[k].Text() << "' "
            << (st == NumberStatus::OutOfRange ? "is out of the range of a double"
                                               : "is not a number");
        this->Fail(vtkErrorCode::FileFormatError, msg.str());
        return false;
      }
    }
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    {
      ++nonFinitePoints;
    }
    if (!std::isfinite(v[3]))
    {
      ++nonFiniteScalars;
    }
    xyz[3 * i] = v[0];
    xyz[3 * i + 1] = v[1];
    xyz[3 * i + 2] = v[2];
    s[i] = v[3];
  }

  vtkIdType* conn = connectivity->GetPointer(0);
  vtkIdType* off = offsets->GetPointer(0);
  vtkIdType degenerate = 0;
  off[0] = 0;
  for (uint64_t t = 0; t < ntets; ++t)
  {
    if (!progress(nverts + t))
    {
      return false;
    }
    if (!cur.NextContentLine(b, e))
    {
      std::ostringstream msg;
      msg << "the file ends after " << t << " of the " << ntets
          << " tetrahedra declared by the header (truncated, or the counts are wrong)";
      this->Fail(vtkErrorCode::PrematureEndOfFileError, msg.str());
      return false;
    }
    const int n = Tokenize(b, e, tok, 4);
    if (n != 4)
    {
      std::ostringstream msg;
      msg << "line " << cur.Line << ": tetrahedron " << t << " needs 4 vertex indices, found "
          << (n > 4 ? std::string("more") : std::to_string(n))
          << " (the counts may not match the file)";
      this->Fail(vtkErrorCode::FileFormatError, msg.str());
      return false;
    }
    vtkIdType* ids = conn + 4 * t;
    for (int k = 0; k < 4; ++k)
    {
      uint64_t id = 0;
      const NumberStatus st = ParseCount(tok[k], id);
      if (st != NumberStatus::Ok || id >= nverts)
      {
        std::ostringstream msg;
        msg << "line " << cur.Line << ": vertex index '" << tok[k].Text() << "' of tetrahedron "
            << t;
        double d;
        if (st == NumberStatus::NotANumber && ParseDouble(tok[k], d) == NumberStatus::Ok &&
          d < 0 && d == std::floor(d))
        {
          msg << " is negative: indices are 0-based and must be below the vertex count "
              << nverts;
        }
        else if (st == NumberStatus::NotANumber)
        {
          msg << " is not an integer (is this a vertex line? the vertex count may be too small)";
        }
        else
        {
          msg << " is out of range: indices are 0-based and must be below the vertex count "
              << nverts;
        }
        this->Fail(vtkErrorCode::FileFormatError, msg.str());
        return false;
      }
      ids[k] = static_cast<vtkIdType>(id);
    }
    if (ids[0] == ids[1] || ids[0] == ids[2] || ids[0] == ids[3] || ids[1] == ids[2] ||
      ids[1] == ids[3] || ids[2] == ids[3])
    {
      ++degenerate;
    }
    off[t + 1] = static_cast<vtkIdType>(4 * (t + 1));
  }

  if (cur.NextContentLine(b, e))
  {
    std::ostringstream msg;
    msg << "line " << cur.Line << ": unexpected data after the " << nverts << " vertices and "
        << ntets << " tetrahedra declared by the header (the counts do not match the file)";
    this->Fail(vtkErrorCode::FileFormatError, msg.str());
    return false;
  }

  vtkNew<vtkPoints> points;
  points->SetData(coords);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  output->GetPointData()->SetScalars(scalars);

  this->NumberOfPointsRead = static_cast<vtkIdType>(nverts);
  this->NumberOfTetrahedraRead = static_cast<vtkIdType>(ntets);
  this->NumberOfNonFinitePoints = nonFinitePoints;
  this->NumberOfNonFiniteScalars = nonFiniteScalars;
  this->NumberOfDegenerateTetrahedra = degenerate;
  if (nonFinitePoints)
  {
    vtkWarningMacro(<< nonFinitePoints << " of the " << nverts
                    << " vertices have a NaN or infinite coordinate (kept as read).");
  }
  if (nonFiniteScalars)
  {
    vtkWarningMacro(<< nonFiniteScalars << " of the " << nverts
                    << " vertices have a NaN or infinite scalar (kept as read; 'Psi Volume' skips "
                       "the tetrahedra that use them).");
  }
  if (degenerate)
  {
    vtkWarningMacro(<< degenerate << " of the " << ntets
                    << " tetrahedra repeat a vertex (zero volume; kept as read).");
  }
  if (ntets == 0)
  {
    vtkWarningMacro("The mesh has no tetrahedra.");
  }
  this->UpdateProgress(1.0);
  return true;
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
