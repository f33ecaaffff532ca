// Tests of vtkPsiOFFTetReader: round trips of valid files (from memory and from disk,
// with the lenient header forms; literature-style files as compact as the format allows, at the
// size check's bound), and every malformed case giving an error event, a message, an
// error code and an empty output, quickly (absurd counts must not allocate or hang).
// Usage: TestOFFReader [TEMP_DIR]
#include "PsiOFFParser.h"
#include "PsiTestCheck.h"
#include "vtkPsiOFFTetReader.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
class Listener : public vtkCommand
{
public:
  static Listener* New() { return new Listener; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->Errors;
      this->LastError = text;
    }
    else if (event == vtkCommand::WarningEvent)
    {
      ++this->Warnings;
      this->LastWarning = text;
    }
  }
  void Reset()
  {
    this->Errors = this->Warnings = 0;
    this->LastError.clear();
    this->LastWarning.clear();
  }
  int Errors = 0;
  int Warnings = 0;
  std::string LastError, LastWarning;
};

struct Fixture
{
  vtkNew<vtkPsiOFFTetReader> Reader;
  vtkNew<Listener> Events;
  vtkNew<Listener> ExecutiveEvents;
  Fixture()
  {
    this->Reader->AddObserver(vtkCommand::ErrorEvent, this->Events);
    this->Reader->AddObserver(vtkCommand::WarningEvent, this->Events);
    // The executive reports "returned failure for request" after a failed RequestData.
    this->Reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->ExecutiveEvents);
  }
  vtkUnstructuredGrid* ReadString(const std::string& text)
  {
    this->Events->Reset();
    this->ExecutiveEvents->Reset();
    this->Reader->ReadFromInputStringOn();
    this->Reader->SetInputString(text);
    this->Reader->Update();
    return this->Reader->GetOutput();
  }
  vtkUnstructuredGrid* ReadFile(const std::string& path)
  {
    this->Events->Reset();
    this->ExecutiveEvents->Reset();
    this->Reader->ReadFromInputStringOff();
    this->Reader->SetFileName(path.c_str());
    this->Reader->Modified();
    this->Reader->Update();
    return this->Reader->GetOutput();
  }
};

const char* const ValidText = "5 2\n"
                              "0 0 0 0.5\n"
                              "1 0 0 1.5\n"
                              "0 1 0 2.5\n"
                              "0 0 1 3.5\n"
                              "1 1 1 -4.25e1\n"
                              "0 1 2 3\n"
                              "1 2 3 4\n";

// A mesh as the reader must return it: x, y, z, s per vertex and four ids per tetrahedron.
struct ExpectedMesh
{
  std::vector<std::array<double, 4>> Vertices;
  std::vector<std::array<vtkIdType, 4>> Tets;
};

// The mesh of ValidText.
ExpectedMesh ValidMesh()
{
  return { { { 0, 0, 0, 0.5 }, { 1, 0, 0, 1.5 }, { 0, 1, 0, 2.5 }, { 0, 0, 1, 3.5 },
             { 1, 1, 1, -42.5 } },
    { { 0, 1, 2, 3 }, { 1, 2, 3, 4 } } };
}

// `ug` is exactly the mesh `m`: points, the active point scalars 'scalars', tetrahedra.
void CheckMesh(vtkUnstructuredGrid* ug, const ExpectedMesh& m, const char* what)
{
  const vtkIdType nv = static_cast<vtkIdType>(m.Vertices.size());
  const vtkIdType nt = static_cast<vtkIdType>(m.Tets.size());
  PSI_CHECK(ug->GetNumberOfPoints() == nv && ug->GetNumberOfCells() == nt,
    "%s: %lld points, %lld cells (expected %lld, %lld)", what,
    static_cast<long long>(ug->GetNumberOfPoints()), static_cast<long long>(ug->GetNumberOfCells()),
    static_cast<long long>(nv), static_cast<long long>(nt));
  if (ug->GetNumberOfPoints() != nv || ug->GetNumberOfCells() != nt)
  {
    return;
  }
  vtkDataArray* s = ug->GetPointData()->GetArray("scalars");
  PSI_CHECK(s != nullptr, "%s: point array 'scalars' exists", what);
  PSI_CHECK(ug->GetPointData()->GetScalars() == s, "%s: 'scalars' are the active scalars", what);
  for (vtkIdType i = 0; i < nv; ++i)
  {
    double p[3];
    ug->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      PSI_CHECK(p[k] == m.Vertices[i][k], "%s: point %lld coordinate %d is %g", what,
        static_cast<long long>(i), k, p[k]);
    }
    PSI_CHECK(!s || s->GetTuple1(i) == m.Vertices[i][3], "%s: scalar %lld is %g", what,
      static_cast<long long>(i), s ? s->GetTuple1(i) : 0.0);
  }
  for (vtkIdType c = 0; c < nt; ++c)
  {
    PSI_CHECK(ug->GetCellType(c) == VTK_TETRA, "%s: cell %lld is a tetrahedron", what,
      static_cast<long long>(c));
    vtkIdType npts;
    const vtkIdType* pts;
    ug->GetCellPoints(c, npts, pts);
    PSI_CHECK(npts == 4, "%s: cell %lld has %lld points", what, static_cast<long long>(c),
      static_cast<long long>(npts));
    for (int k = 0; k < 4 && npts == 4; ++k)
    {
      PSI_CHECK(pts[k] == m.Tets[c][k], "%s: cell %lld point %d is %lld", what,
        static_cast<long long>(c), k, static_cast<long long>(pts[k]));
    }
  }
}

// The mesh of ValidText, checked exactly.
void CheckValidMesh(vtkUnstructuredGrid* ug, const char* what)
{
  CheckMesh(ug, ValidMesh(), what);
}

void TestValid(Fixture& f)
{
  CheckValidMesh(f.ReadString(ValidText), "plain");
  PSI_CHECK(f.Events->Errors == 0 && f.Events->Warnings == 0, "plain: no error or warning (%s%s)",
    f.Events->LastError.c_str(), f.Events->LastWarning.c_str());
  PSI_CHECK(f.Reader->GetErrorCode() == vtkErrorCode::NoError, "plain: no error code");
  PSI_CHECK(std::string(f.Reader->GetLastError()).empty(), "plain: no last error");

  // Lenient forms: comments, OFF keyword (own line, same line, lower case), blank lines, CRLF,
  // tabs, '+' signs, no final newline, a UTF-8 byte-order mark.
  const std::string body = "0 0 0 0.5\n1 0 0 1.5\n0 1 0 2.5\n0 0 1 3.5\n1 1 1 -4.25e1\n"
                           "0 1 2 3\n1 2 3 4";
  const std::string variants[] = {
    "# a tetrahedral mesh\n# second comment\n5 2\n" + body + "\n",
    "OFF\n5 2\n" + body + "\n",
    "off 5 2\n" + body,
    "\n\n  \n# c\nOFF\n\n# counts follow\n  5\t2  \n\n" + body + "\n\n# end\n",
    "\xEF\xBB\xBF"
    "5 2\n" +
      body + "\n",
    "5 2\r\n0 0 0 0.5\r\n1 0 0 +1.5\r\n0 1 0 2.5\r\n0 0 1 3.5\r\n1 1 1 -4.25e1\r\n0 1 2 3\r\n"
    "1\t2\t3\t4\r\n",
    "5 2\n0 0 0 0.5\n1 0 0 1.5\n# a comment between vertices\n0 1 0 2.5\n0 0 1 3.5\n"
    "1 1 1 -42.5\n\n0 1 2 3\n1 2 3 4\n",
  };
  int k = 0;
  for (const std::string& v : variants)
  {
    const std::string what = "lenient form " + std::to_string(k++);
    CheckValidMesh(f.ReadString(v), what.c_str());
    PSI_CHECK(
      f.Events->Errors == 0, "%s: no error (%s)", what.c_str(), f.Events->LastError.c_str());
  }

  // NaN/Inf coordinates and scalars are accepted, counted and reported.
  vtkUnstructuredGrid* ug = f.ReadString("4 1\n0 0 0 nan\n1 0 0 inf\nnan 1 0 2\n0 0 -inf 3\n"
                                         "0 1 2 3\n");
  PSI_CHECK(ug->GetNumberOfPoints() == 4 && ug->GetNumberOfCells() == 1,
    "non-finite values are read (%lld points)", static_cast<long long>(ug->GetNumberOfPoints()));
  PSI_CHECK(f.Events->Errors == 0, "non-finite values: no error");
  PSI_CHECK(f.Reader->GetNumberOfNonFinitePoints() == 2, "2 non-finite points (%lld)",
    static_cast<long long>(f.Reader->GetNumberOfNonFinitePoints()));
  PSI_CHECK(f.Reader->GetNumberOfNonFiniteScalars() == 2, "2 non-finite scalars (%lld)",
    static_cast<long long>(f.Reader->GetNumberOfNonFiniteScalars()));
  PSI_CHECK(f.Events->Warnings == 2, "non-finite coordinates and scalars are reported (%d)",
    f.Events->Warnings);
  if (ug->GetNumberOfPoints() == 4)
  {
    PSI_CHECK(std::isnan(ug->GetPointData()->GetScalars()->GetTuple1(0)), "NaN scalar kept");
    PSI_CHECK(std::isnan(ug->GetPoint(2)[0]), "NaN coordinate kept");
  }

  // Repeated vertices: kept, counted, reported.
  ug = f.ReadString("4 2\n0 0 0 0\n1 0 0 1\n0 1 0 2\n0 0 1 3\n0 1 2 3\n0 0 2 3\n");
  PSI_CHECK(ug->GetNumberOfCells() == 2 && f.Reader->GetNumberOfDegenerateTetrahedra() == 1,
    "a tetrahedron repeating a vertex is kept and counted");
  PSI_CHECK(f.Events->Warnings == 1 && f.Events->LastWarning.find("repeat") != std::string::npos,
    "and reported (%s)", f.Events->LastWarning.c_str());

  // An empty mesh is valid, with a warning.
  ug = f.ReadString("0 0\n");
  PSI_CHECK(f.Events->Errors == 0 && ug->GetNumberOfPoints() == 0, "'0 0' is an empty mesh");
  PSI_CHECK(f.Events->Warnings == 1, "'0 0' warns that there are no tetrahedra");

  // A larger random mesh round-trips exactly (17 significant digits).
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  const int nv = 2000, nt = 20000;
  std::vector<double> vals(4 * nv);
  std::vector<vtkIdType> ids(4 * nt);
  std::ostringstream os;
  os.precision(17);
  os << nv << " " << nt << "\n";
  for (int i = 0; i < nv; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      vals[4 * i + c] = u(rng);
      os << vals[4 * i + c] << (c == 3 ? "\n" : " ");
    }
  }
  for (int t = 0; t < nt; ++t)
  {
    for (int c = 0; c < 4; ++c)
    {
      ids[4 * t + c] = static_cast<vtkIdType>(rng() % nv);
      os << ids[4 * t + c] << (c == 3 ? "\n" : " ");
    }
  }
  ug = f.ReadString(os.str());
  PSI_CHECK(ug->GetNumberOfPoints() == nv && ug->GetNumberOfCells() == nt,
    "random mesh: %lld points, %lld cells", static_cast<long long>(ug->GetNumberOfPoints()),
    static_cast<long long>(ug->GetNumberOfCells()));
  if (ug->GetNumberOfPoints() == nv && ug->GetNumberOfCells() == nt)
  {
    int bad = 0;
    vtkDataArray* s = ug->GetPointData()->GetScalars();
    for (int i = 0; i < nv; ++i)
    {
      double p[3];
      ug->GetPoint(i, p);
      bad += p[0] != vals[4 * i] || p[1] != vals[4 * i + 1] || p[2] != vals[4 * i + 2] ||
        s->GetTuple1(i) != vals[4 * i + 3];
    }
    for (int t = 0; t < nt; ++t)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      ug->GetCellPoints(t, npts, pts);
      for (int c = 0; c < 4; ++c)
      {
        bad += pts[c] != ids[4 * t + c];
      }
    }
    PSI_CHECK(bad == 0, "random mesh round-trips exactly (%d mismatches)", bad);
  }
}

// The unit cube's corners (vertex i at (i & 1, i >> 1 & 1, i >> 2 & 1), scalar i) and its 6
// Kuhn tetrahedra around the diagonal 0-7; or, with `single`, the tetrahedron of its corners
// 0, 1, 2, 4.
ExpectedMesh CubeMesh(bool single)
{
  ExpectedMesh m;
  for (int i = 0; i < (single ? 5 : 8); ++i)
  {
    if (!single || i != 3)
    {
      m.Vertices.push_back({ double(i & 1), double(i >> 1 & 1), double(i >> 2 & 1), double(i) });
    }
  }
  m.Tets = single ? std::vector<std::array<vtkIdType, 4>>{ { 0, 1, 2, 3 } }
                  : std::vector<std::array<vtkIdType, 4>>{ { 0, 1, 3, 7 }, { 0, 1, 5, 7 },
                      { 0, 2, 3, 7 }, { 0, 2, 6, 7 }, { 0, 4, 5, 7 }, { 0, 4, 6, 7 } };
  return m;
}

// `m` as compactly as the format allows (single-digit values, single spaces, each data line
// "a b c d\n"), after `header` (the counts line); the last line without its newline unless
// `finalNewline`.
std::string CompactText(const ExpectedMesh& m, const std::string& header, bool finalNewline)
{
  std::ostringstream os;
  os << header;
  for (const auto& v : m.Vertices)
  {
    os << v[0] << ' ' << v[1] << ' ' << v[2] << ' ' << v[3] << '\n';
  }
  for (const auto& t : m.Tets)
  {
    os << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  }
  std::string text = os.str();
  if (!finalNewline)
  {
    text.pop_back();
  }
  return text;
}

// Literature-style files written as compactly as the format allows: with no newline after the
// last line they hold exactly MinBytesPerLine bytes a line less one, the least the size check
// accepts. Each must read exactly, from memory and from disk, with and without the keyword.
void TestCompact(Fixture& f, const std::string& dir)
{
  const std::string path = dir + "/psi_off_reader_compact.off";
  for (const bool single : { true, false })
  {
    const ExpectedMesh m = CubeMesh(single);
    const size_t lines = m.Vertices.size() + m.Tets.size();
    const std::string counts =
      std::to_string(m.Vertices.size()) + " " + std::to_string(m.Tets.size()) + "\n";
    const std::string body = CompactText(m, "", false);
    PSI_CHECK(body.size() == psi::OFFParser::MinBytesPerLine * lines - 1,
      "compact body: %zu bytes for %zu lines", body.size(), lines);
    const std::string forms[] = { counts + body, "OFF\n" + counts + body, "OFF " + counts + body,
      CompactText(m, counts, true), "# HAVS\r\n" + counts + body };
    int k = 0;
    for (const std::string& text : forms)
    {
      const std::string what = std::string(single ? "compact tetrahedron" : "compact cube") +
        ", form " + std::to_string(k++);
      CheckMesh(f.ReadString(text), m, (what + " (memory)").c_str());
      PSI_CHECK(
        f.Events->Errors == 0, "%s: no error (%s)", what.c_str(), f.Events->LastError.c_str());
      std::ofstream(path, std::ios::binary) << text;
      CheckMesh(f.ReadFile(path), m, (what + " (file)").c_str());
      PSI_CHECK(f.Events->Errors == 0 && f.Reader->CanReadFile(path.c_str()) == 1,
        "%s file: read without error (%s)", what.c_str(), f.Events->LastError.c_str());
    }
    // One byte less cannot hold the lines: the size check rejects it.
    f.ReadString(counts + body.substr(0, body.size() - 1));
    PSI_CHECK(f.Events->Errors == 1 &&
        f.Events->LastError.find("bytes follow the header") != std::string::npos,
      "compact, last byte cut: too short (%s)", f.Events->LastError.c_str());
  }
  std::remove(path.c_str());
}

struct BadCase
{
  const char* Name;
  std::string Text;
  const char* Expect; // a substring the error message must contain
};

void TestMalformed(Fixture& f)
{
  // Vertex lines long enough that the size check (8 bytes a line) lets the line checks speak.
  const std::string v5 = "0.0 0.0 0.0 0.0\n1.0 0.0 0.0 1.0\n0.0 1.0 0.0 2.0\n0.0 0.0 1.0 3.0\n"
                         "1.0 1.0 1.0 4.0\n";
  const std::string v4 = "0.0 0.0 0.0 0.0\n1.0 0.0 0.0 1.0\n0.0 1.0 0.0 2.0\n0.0 0.0 1.0 3.0\n";
  const BadCase cases[] = {
    { "empty input", "", "empty" },
    { "only comments and blank lines", "# nothing\n\n   \n# here\n", "empty" },
    { "OFF keyword only", "OFF\n", "OFF" },
    { "one count", "5\n" + v5, "nverts ntets" },
    { "polygonal OFF surface",
      "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n"
      "3 0 2 3\n3 1 2 3\n",
      "polygonal OFF surface" },
    { "non-integer count", "5 x\n" + v5 + "0 1 2 3\n", "not a non-negative integer" },
    { "negative count", "-5 1\n" + v5 + "0 1 2 3\n", "not a non-negative integer" },
    { "fractional count", "5.0 1\n" + v5 + "0 1 2 3\n", "not a non-negative integer" },
    { "count overflowing 64 bits", "99999999999999999999999 1\n" + v5, "absurdly large" },
    { "absurd counts for the file size", "1000000000000 1000000000000\n" + v5 + "0 1 2 3\n",
      "bytes follow the header" },
    { "counts near 2^63", "9223372036854775807 9223372036854775807\n" + v5 + "0 1 2 3\n",
      "bytes follow the header" },
    { "vertex count larger than the file", "1000 1\n" + v5 + "0 1 2 3\n",
      "bytes follow the header" },
    { "file too short for its counts",
      "5 2\n0 0 0 0\n1 0 0 1\n0 1 0 2\n0 0 1 3\n1 1 1 4\n"
      "0 1 2 3\n",
      "bytes follow the header" },
    { "fewer vertices than declared", "7 1\n" + v5 + "0 1 2 3\n", "6 of the 7 vertices" },
    { "truncated in the tetrahedra", "5 1\n" + v5, "0 of the 1 tetrahedra" },
    { "truncated after a tetrahedron", "5 2\n" + v5 + "0 1 2 3\n", "1 of the 2 tetrahedra" },
    { "truncated mid-line", "5 2\n" + v5 + "0 1 2 3\n1 2", "found 2" },
    { "truncated mid-vertex", "5 1\n" + v4 + "1.0 1.", "found 2" },
    { "more tetrahedra than declared", "5 1\n" + v5 + "0 1 2 3\n1 2 3 4\n", "unexpected data" },
    { "more vertices than declared (read as a tetrahedron)", "4 1\n" + v5 + "0 1 2 3\n",
      "not an integer" },
    { "vertex with 3 values", "5 1\n" + v4 + "1.0 1.0 1.0\n0 1 2 3\n", "found 3" },
    { "vertex with 5 values", "5 1\n" + v4 + "1.0 1.0 1.0 4.0 9.0\n0 1 2 3\n", "found more" },
    { "non-number coordinate", "5 1\n" + v4 + "1.0 abc 1.0 4.0\n0 1 2 3\n",
      "y of vertex 4 'abc' is not a number" },
    { "number with trailing junk", "5 1\n" + v4 + "1.0 1.0 1.0 4.0x\n0 1 2 3\n",
      "is not a number" },
    { "coordinate out of double range", "5 1\n" + v4 + "1e999 1.0 1.0 4.0\n0 1 2 3\n",
      "out of the range" },
    { "index equal to the vertex count", "5 1\n" + v5 + "0 1 2 5\n", "out of range" },
    { "huge index", "5 1\n" + v5 + "0 1 2 123456789012345678901234567890\n", "out of range" },
    { "negative index", "5 1\n" + v5 + "0 -1 2 3\n", "negative" },
    { "fractional index", "5 1\n" + v5 + "0 1.5 2 3\n", "not an integer" },
    { "tetrahedron with 3 indices", "5 1\n" + v5 + "0 1 2\n", "found 3" },
    { "tetrahedron with 5 indices (OFF polygon style)", "5 1\n" + v5 + "4 0 1 2 3\n",
      "found more" },
    { "NUL bytes", "5 1\n" + v4 + std::string("1.0 1.0\0 1.0 4.0\n", 17) + "0 1 2 3\n",
      "is not a number" },
    { "binary junk",
      std::string("\x7f"
                  "ELF\x02\x01\x01\0\0\0\0\xff\xfe",
        14),
      "'\\x7fELF" },
  };
  for (const BadCase& c : cases)
  {
    // First a valid read, so that a failure must also clear the previous output.
    f.ReadString(ValidText);
    const auto t0 = std::chrono::steady_clock::now();
    vtkUnstructuredGrid* ug = f.ReadString(c.Text);
    const double secs =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-52s -> %s\n", c.Name, f.Reader->GetLastError());
    PSI_CHECK(f.Events->Errors == 1, "%s: one error event (%d)", c.Name, f.Events->Errors);
    PSI_CHECK(f.Events->LastError.find(c.Expect) != std::string::npos,
      "%s: the message names the problem ('%s' in '%s')", c.Name, c.Expect,
      f.Events->LastError.c_str());
    PSI_CHECK(std::string(f.Reader->GetLastError()).find(c.Expect) != std::string::npos,
      "%s: GetLastError ('%s')", c.Name, f.Reader->GetLastError());
    PSI_CHECK(f.Reader->GetErrorCode() != vtkErrorCode::NoError, "%s: error code set", c.Name);
    PSI_CHECK(ug->GetNumberOfPoints() == 0 && ug->GetNumberOfCells() == 0,
      "%s: empty output (%lld points, %lld cells)", c.Name,
      static_cast<long long>(ug->GetNumberOfPoints()),
      static_cast<long long>(ug->GetNumberOfCells()));
    PSI_CHECK(ug->GetPointData()->GetNumberOfArrays() == 0, "%s: no point arrays", c.Name);
    PSI_CHECK(f.Reader->GetNumberOfPointsRead() == 0, "%s: no points counted", c.Name);
    PSI_CHECK(secs < 1.0, "%s: fails fast (%.3f s)", c.Name, secs);
  }
}

void TestFiles(Fixture& f, const std::string& dir)
{
  const std::string good = dir + "/psi_off_reader_good.off";
  const std::string surface = dir + "/psi_off_reader_surface.off";
  const std::string truncated = dir + "/psi_off_reader_truncated.off";
  {
    std::ofstream(good) << "# HAVS style\n" << ValidText;
    std::ofstream(surface) << "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n";
    const std::string full = ValidText;
    std::ofstream(truncated) << full.substr(0, full.size() - 5);
  }
  CheckValidMesh(f.ReadFile(good), "file");
  PSI_CHECK(f.Events->Errors == 0, "file: no error (%s)", f.Events->LastError.c_str());
  PSI_CHECK(f.Reader->CanReadFile(good.c_str()) == 1, "CanReadFile accepts a tetrahedral OFF");
  PSI_CHECK(f.Reader->CanReadFile(surface.c_str()) == 0, "CanReadFile refuses a surface OFF");
  PSI_CHECK(f.Reader->CanReadFile((dir + "/no_such.off").c_str()) == 0,
    "CanReadFile refuses a missing file");

  struct FileCase
  {
    const char* Name;
    std::string Path;
    const char* Expect;
  } cases[] = {
    { "missing file", dir + "/psi_off_reader_no_such_file.off", "no such file" },
    { "directory", dir, "not a regular file" },
    { "truncated file", truncated, "found 2" },
    { "surface OFF file", surface, "polygonal OFF surface" },
  };
  for (const FileCase& c : cases)
  {
    f.ReadFile(good);
    vtkUnstructuredGrid* ug = f.ReadFile(c.Path);
    std::printf("%-52s -> %s\n", c.Name, f.Reader->GetLastError());
    PSI_CHECK(f.Events->Errors == 1 && f.Events->LastError.find(c.Expect) != std::string::npos,
      "%s: error naming the problem ('%s' in '%s')", c.Name, c.Expect, f.Events->LastError.c_str());
    PSI_CHECK(
      ug->GetNumberOfPoints() == 0 && ug->GetNumberOfCells() == 0, "%s: empty output", c.Name);
  }
  f.Events->Reset();
  f.Reader->ReadFromInputStringOff();
  f.Reader->SetFileName(nullptr);
  f.Reader->Update();
  PSI_CHECK(f.Events->Errors == 1 && f.Events->LastError.find("no file name") != std::string::npos,
    "no file name: error (%s)", f.Events->LastError.c_str());
  std::remove(good.c_str());
  std::remove(surface.c_str());
  std::remove(truncated.c_str());
}
} // namespace

int main(int argc, char* argv[])
{
  std::string dir = argc > 1 ? argv[1] : "";
  if (dir.empty())
  {
    const char* tmp = std::getenv("TMPDIR");
    dir = tmp && *tmp ? tmp : "/tmp";
  }
  Fixture f;
  TestValid(f);
  TestMalformed(f);
  TestCompact(f, dir);
  TestFiles(f, dir);
  std::printf("TestOFFReader: %s (%d failures)\n", psitest::Failures() ? "FAILED" : "passed",
    psitest::Failures());
  return psitest::Failures() ? 1 : 0;
}
