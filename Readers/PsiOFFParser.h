// PsiOFFParser: the sections of a tetrahedral OFF mesh (the ".off" files of the unstructured-
// volume literature, e.g. HAVS and HAPT):
//
//     nverts ntets
//     x y z s        (nverts lines)
//     a b c d        (ntets lines, 0-based vertex indices)
//
// with blank and '#' comment lines anywhere and an optional "OFF" keyword before the counts. The
// caller reads the header, checks the counts against the size, then the vertex and tetrahedron
// lines one at a time, then the end; each step returns false on bad input, with the reason in
// ErrorMessage() (one line, with the line number where there is one). Plain C++ (no VTK),
// testable alone; vtkPsiOFFTetReader is the VTK reader built on it.
#ifndef PsiOFFParser_h
#define PsiOFFParser_h

#include "PsiOFFTokenizer.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace psi
{
class OFFParser
{
public:
  /// The shortest possible data line is "0 0 0 0\n": 8 bytes (the last line may lack its '\n').
  static constexpr uint64_t MinBytesPerLine = 8;

  enum class ErrorKind
  {
    None,
    Format,   ///< malformed content
    Truncated ///< the file ends before the declared lines, or is too short for them
  };

  /// Parses [data, data + size), which must outlive the parser.
  OFFParser(const char* data, size_t size);

  /// The header: optional "OFF" keyword, then exactly two non-negative counts.
  bool ReadHeader();
  /// Whether the bytes after the header can hold the declared lines, and each count is at most
  /// maxCount (call before allocating anything for the mesh).
  bool CheckCountsFitSize(uint64_t maxCount);
  /// Vertex line i: x y z s.
  bool ReadVertex(uint64_t i, double xyzs[4]);
  /// Tetrahedron line t: four vertex indices, each below the vertex count.
  bool ReadTetrahedron(uint64_t t, uint64_t ids[4]);
  /// No content after the last tetrahedron.
  bool ReadEnd();

  uint64_t GetNumberOfVertices() const { return this->NumberOfVertices; }
  uint64_t GetNumberOfTetrahedra() const { return this->NumberOfTetrahedra; }
  ErrorKind GetErrorKind() const { return this->Error; }
  const std::string& GetErrorMessage() const { return this->Message; }

private:
  bool Fail(ErrorKind kind, const std::string& message);
  bool ReadCounts(int n, int first, const off::Token* tok);
  int NextLineTokens(off::Token* tok); // -1 at the end of the buffer
  bool NextRecord(off::Token tok[4], uint64_t i, uint64_t declared, const char* plural,
    const char* singular, const char* needs);
  std::string IndexError(uint64_t t, const off::Token& tok, off::NumberStatus st) const;

  off::LineCursor Cursor;
  uint64_t NumberOfVertices = 0;
  uint64_t NumberOfTetrahedra = 0;
  ErrorKind Error = ErrorKind::None;
  std::string Message;
};
} // namespace psi

#endif
