#include "PsiOFFParser.h"

#include <cmath>
#include <sstream>

namespace psi
{
using off::NumberStatus;
using off::Token;

OFFParser::OFFParser(const char* data, size_t size)
  : Cursor(data, size)
{
}

bool OFFParser::Fail(ErrorKind kind, const std::string& message)
{
  this->Error = kind;
  this->Message = message;
  return false;
}

int OFFParser::NextLineTokens(Token* tok)
{
  const char *b, *e;
  if (!this->Cursor.NextContentLine(b, e))
  {
    return -1;
  }
  return off::Tokenize(b, e, tok, 4);
}

bool OFFParser::ReadHeader()
{
  Token tok[4];
  int n = this->NextLineTokens(tok);
  if (n < 0)
  {
    return this->Fail(ErrorKind::Format, "the file is empty (no 'nverts ntets' header)");
  }
  int first = 0;
  if (n >= 1 && off::IsOFFKeyword(tok[0]))
  {
    first = 1;
    if (n == 1)
    {
      n = this->NextLineTokens(tok);
      if (n < 0)
      {
        return this->Fail(
          ErrorKind::Format, "the file ends after its 'OFF' keyword (no 'nverts ntets' counts)");
      }
      first = 0;
    }
  }
  return this->ReadCounts(n, first, tok);
}

// The counts of the header line, tokens tok[first, n) (n == 5 means "more than 4 tokens").
bool OFFParser::ReadCounts(int n, int first, const Token* tok)
{
  const int counts = n - first;
  std::ostringstream msg;
  msg << "line " << this->Cursor.Line << ": ";
  uint64_t a;
  if (counts >= 3 && off::ParseCount(tok[first], a) == NumberStatus::Ok)
  {
    msg << "the header has three or more counts: this looks like a polygonal OFF surface "
           "('nverts nfaces nedges'), not a tetrahedral mesh ('nverts ntets')";
    return this->Fail(ErrorKind::Format, msg.str());
  }
  if (counts != 2)
  {
    msg << "expected the header 'nverts ntets' (two non-negative integers), found "
        << (counts >= 3 ? std::string("3 or more values") : std::to_string(counts) + " value(s)");
    if (counts >= 1)
    {
      msg << " starting with '" << tok[first].Text() << "'";
    }
    return this->Fail(ErrorKind::Format, msg.str());
  }
  uint64_t* out[2] = { &this->NumberOfVertices, &this->NumberOfTetrahedra };
  const char* what[2] = { "vertex count", "tetrahedron count" };
  for (int k = 0; k < 2; ++k)
  {
    const NumberStatus s = off::ParseCount(tok[first + k], *out[k]);
    if (s != NumberStatus::Ok)
    {
      msg << "the " << what[k] << " '" << tok[first + k].Text() << "' "
          << (s == NumberStatus::OutOfRange ? "is absurdly large"
                                            : "is not a non-negative integer");
      return this->Fail(ErrorKind::Format, msg.str());
    }
  }
  return true;
}

bool OFFParser::CheckCountsFitSize(uint64_t maxCount)
{
  const uint64_t nverts = this->NumberOfVertices, ntets = this->NumberOfTetrahedra;
  const size_t remaining = this->Cursor.Remaining();
  const uint64_t lines = nverts + ntets; // both are < 2^64 / 2 here or the checks below fail
  const bool fits = nverts <= remaining && ntets <= remaining &&
    lines * MinBytesPerLine <= static_cast<uint64_t>(remaining) + 1 && nverts <= maxCount &&
    ntets <= maxCount;
  if (!fits)
  {
    std::ostringstream msg;
    msg << "the header declares " << nverts << " vertices and " << ntets
        << " tetrahedra, which need at least " << MinBytesPerLine << " bytes per line, but only "
        << remaining << " bytes follow the header: the counts are wrong or the file is truncated";
    return this->Fail(ErrorKind::Truncated, msg.str());
  }
  return true;
}

// The four tokens of record i of a section of `declared` records: the file must not end before
// it (a truncation) and the line must hold exactly four values (a format error).
bool OFFParser::NextRecord(Token tok[4], uint64_t i, uint64_t declared, const char* plural,
  const char* singular, const char* needs)
{
  const int n = this->NextLineTokens(tok);
  if (n < 0)
  {
    std::ostringstream msg;
    msg << "the file ends after " << i << " of the " << declared << " " << plural
        << " declared by the header (truncated, or the counts are wrong)";
    return this->Fail(ErrorKind::Truncated, msg.str());
  }
  if (n != 4)
  {
    std::ostringstream msg;
    msg << "line " << this->Cursor.Line << ": " << singular << " " << i << " needs " << needs
        << ", found " << (n > 4 ? std::string("more") : std::to_string(n))
        << " (the counts may not match the file)";
    return this->Fail(ErrorKind::Format, msg.str());
  }
  return true;
}

bool OFFParser::ReadVertex(uint64_t i, double xyzs[4])
{
  static const char* const field[4] = { "x", "y", "z", "s" };
  Token tok[4];
  if (!this->NextRecord(tok, i, this->NumberOfVertices, "vertices", "vertex", "4 values 'x y z s'"))
  {
    return false;
  }
  for (int k = 0; k < 4; ++k)
  {
    const NumberStatus st = off::ParseDouble(tok[k], xyzs[k]);
    if (st != NumberStatus::Ok)
    {
      std::ostringstream msg;
      msg << "line " << this->Cursor.Line << ": " << field[k] << " of vertex " << i << " '"
          << tok[k].Text() << "' "
          << (st == NumberStatus::OutOfRange ? "is out of the range of a double"
                                             : "is not a number");
      return this->Fail(ErrorKind::Format, msg.str());
    }
  }
  return true;
}

bool OFFParser::ReadTetrahedron(uint64_t t, uint64_t ids[4])
{
  Token tok[4];
  if (!this->NextRecord(
        tok, t, this->NumberOfTetrahedra, "tetrahedra", "tetrahedron", "4 vertex indices"))
  {
    return false;
  }
  for (int k = 0; k < 4; ++k)
  {
    const NumberStatus st = off::ParseCount(tok[k], ids[k]);
    if (st != NumberStatus::Ok || ids[k] >= this->NumberOfVertices)
    {
      return this->Fail(ErrorKind::Format, this->IndexError(t, tok[k], st));
    }
  }
  return true;
}

// Why vertex index `tok` of tetrahedron t, parsed with status st, is rejected.
std::string OFFParser::IndexError(uint64_t t, const Token& tok, NumberStatus st) const
{
  std::ostringstream msg;
  msg << "line " << this->Cursor.Line << ": vertex index '" << tok.Text() << "' of tetrahedron "
      << t;
  double d;
  if (st == NumberStatus::NotANumber && off::ParseDouble(tok, d) == NumberStatus::Ok && d < 0 &&
    d == std::floor(d))
  {
    msg << " is negative: indices are 0-based and must be below the vertex count "
        << this->NumberOfVertices;
  }
  else if (st == NumberStatus::NotANumber)
  {
    msg << " is not an integer (is this a vertex line? the vertex count may be too small)";
  }
  else
  {
    msg << " is out of range: indices are 0-based and must be below the vertex count "
        << this->NumberOfVertices;
  }
  return msg.str();
}

bool OFFParser::ReadEnd()
{
  const char *b, *e;
  if (this->Cursor.NextContentLine(b, e))
  {
    std::ostringstream msg;
    msg << "line " << this->Cursor.Line << ": unexpected data after the " << this->NumberOfVertices
        << " vertices and " << this->NumberOfTetrahedra
        << " tetrahedra declared by the header (the counts do not match the file)";
    return this->Fail(ErrorKind::Format, msg.str());
  }
  return true;
}
} // namespace psi
