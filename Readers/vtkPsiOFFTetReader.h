/**
 * @class   vtkPsiOFFTetReader
 * @brief   Reads the tetrahedral ".off" meshes of the unstructured-volume literature (HAVS, HAPT).
 *
 * The format is ASCII:
 *
 *     nverts ntets
 *     x y z s        (nverts lines)
 *     a b c d        (ntets lines, 0-based vertex indices)
 *
 * The output is a vtkUnstructuredGrid of VTK_TETRA cells with the point array "scalars" (the
 * active scalars).
 *
 * Leniency, only where it is unambiguous: blank lines and whole-line comments starting with '#'
 * are skipped anywhere; an "OFF" keyword before the counts (on its own line or on the counts'
 * line) is accepted; CRLF line ends and tabs are accepted. Everything else is validated and a
 * malformed file gives one clear error (vtkErrorMacro, with the line number), an empty output and
 * GetLastError()/GetErrorCode() set:
 *  - a header that is not exactly two non-negative integers (a polygonal OFF surface with three
 *    counts is recognised and named as such);
 *  - counts that do not match the file (too few lines: truncated; extra data after the last
 *    tetrahedron; a line with the wrong number of values);
 *  - counts too large for the file's size (checked before anything is allocated, so a forged
 *    header cannot make the reader allocate more than the file could describe);
 *  - values that are not numbers, indices that are not integers or out of [0, nverts).
 * NaN/Inf coordinates and scalars are accepted but counted and reported with a warning (the
 * 'Psi Volume' mapper skips tetrahedra with non-finite scalars). Tetrahedra that repeat a vertex
 * are kept, counted and reported.
 *
 * Input is a file (SetFileName) or, with ReadFromInputString on, bytes in memory
 * (SetInputString), which may contain NUL bytes. In parallel, piece 0 reads the whole mesh and
 * the other pieces are empty (redistribute with RedistributeDataSet).
 *
 * The parsing itself is psi::OFFParser (PsiOFFParser.h, plain C++ without VTK); this class is the
 * pipeline glue: file or string input, arrays, errors, warnings and progress.
 */
#ifndef vtkPsiOFFTetReader_h
#define vtkPsiOFFTetReader_h

#include "PsiVolumeReadersModule.h"
#include "vtkUnstructuredGridAlgorithm.h"

#include <cstdint>
#include <string>

namespace psi
{
class OFFParser;
}

class PSIVOLUMEREADERS_EXPORT vtkPsiOFFTetReader : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkPsiOFFTetReader* New();
  vtkTypeMacro(vtkPsiOFFTetReader, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);

  ///@{
  /// Read from the string set by SetInputString instead of the file (default off).
  vtkSetMacro(ReadFromInputString, bool);
  vtkGetMacro(ReadFromInputString, bool);
  vtkBooleanMacro(ReadFromInputString, bool);
  ///@}

  ///@{
  /// The bytes to read when ReadFromInputString is on; may contain NUL bytes.
  void SetInputString(const char* data, size_t length);
  void SetInputString(const std::string& s);
  const std::string& GetInputString() const { return this->InputString; }
  ///@}

  /// 1 when the file's header looks like a tetrahedral OFF mesh (two counts), 0 otherwise
  /// (e.g. a polygonal OFF surface, whose header has three counts). ParaView's reader factory
  /// calls it to choose between this reader and its own surface OFF reader.
  virtual int CanReadFile(const char* filename);

  /// The test behind CanReadFile, shared with vtkPsiOFFSurfaceReader (its complement).
  static bool IsTetrahedralOFF(const char* filename);

  ///@{
  /// What the last read found: declared counts, points with a NaN/Inf coordinate, points with a
  /// NaN/Inf scalar, tetrahedra with a repeated vertex. All are 0 after a failed read.
  vtkGetMacro(NumberOfPointsRead, vtkIdType);
  vtkGetMacro(NumberOfTetrahedraRead, vtkIdType);
  vtkGetMacro(NumberOfNonFinitePoints, vtkIdType);
  vtkGetMacro(NumberOfNonFiniteScalars, vtkIdType);
  vtkGetMacro(NumberOfDegenerateTetrahedra, vtkIdType);
  ///@}

  /// The error of the last read ("" when it succeeded).
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkPsiOFFTetReader();
  ~vtkPsiOFFTetReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  bool ReadFromInputString = false;
  std::string InputString;
  std::string LastError;
  vtkIdType NumberOfPointsRead = 0;
  vtkIdType NumberOfTetrahedraRead = 0;
  vtkIdType NumberOfNonFinitePoints = 0;
  vtkIdType NumberOfNonFiniteScalars = 0;
  vtkIdType NumberOfDegenerateTetrahedra = 0;

private:
  vtkPsiOFFTetReader(const vtkPsiOFFTetReader&) = delete;
  void operator=(const vtkPsiOFFTetReader&) = delete;

  // The steps of RequestData: the bytes of the file, then the mesh parsed from them by
  // psi::OFFParser into the arrays of a Mesh (defined in the .cxx). Each returns false, after
  // Fail, when reading cannot go on.
  struct Mesh;
  bool LoadFile(std::string& buffer);
  bool Parse(const char* data, size_t size, vtkUnstructuredGrid* output);
  bool AllocateMesh(const psi::OFFParser& parser, Mesh& mesh);
  bool ReadVertices(psi::OFFParser& parser, Mesh& mesh);
  bool ReadTetrahedra(psi::OFFParser& parser, Mesh& mesh);
  bool Progress(uint64_t done, uint64_t total); // false when aborted
  void StoreMesh(Mesh& mesh, vtkUnstructuredGrid* output);
  void ReportMesh(const psi::OFFParser& parser, const Mesh& mesh);
  bool FailParse(const psi::OFFParser& parser);
  void Fail(unsigned long code, const std::string& message);
};

#endif
