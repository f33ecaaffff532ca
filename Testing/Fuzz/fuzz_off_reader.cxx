// libFuzzer target for vtkPsiOFFTetReader: feeds arbitrary bytes to the reader through
// its in-memory path (ReadFromInputString) and checks, beyond the sanitizers, that the output is
// either empty with an error, or a consistent mesh of tetrahedra with in-range indices.
// Built with -DPSI_BUILD_FUZZERS=ON and clang (Testing/Readers.cmake); seeds in corpus/.
#include "vtkPsiOFFTetReader.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace
{
// Swallows the reader's (expected) error and warning events so that fuzzing is quiet, while the
// code that builds the messages still runs.
class Quiet : public vtkCommand
{
public:
  static Quiet* New() { return new Quiet; }
  void Execute(vtkObject*, unsigned long, void*) override {}
};

[[noreturn]] void Violation(const char* what)
{
  std::fprintf(stderr, "fuzz_off_reader: invariant violated: %s\n", what);
  std::abort();
}

vtkPsiOFFTetReader* TheReader()
{
  static vtkPsiOFFTetReader* reader = []
  {
    vtkPsiOFFTetReader* r = vtkPsiOFFTetReader::New();
    vtkNew<Quiet> quiet;
    r->AddObserver(vtkCommand::ErrorEvent, quiet);
    r->AddObserver(vtkCommand::WarningEvent, quiet);
    r->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
    r->ReadFromInputStringOn();
    return r;
  }();
  return reader;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkPsiOFFTetReader* reader = TheReader();
  reader->SetInputString(reinterpret_cast<const char*>(data), size);
  reader->Update();
  vtkUnstructuredGrid* ug = reader->GetOutput();
  const bool failed = reader->GetLastError()[0] != '\0';
  if (failed)
  {
    if (ug->GetNumberOfPoints() != 0 || ug->GetNumberOfCells() != 0 ||
      ug->GetPointData()->GetNumberOfArrays() != 0)
    {
      Violation("a failed read left a non-empty output");
    }
    return 0;
  }
  const vtkIdType np = ug->GetNumberOfPoints(), nc = ug->GetNumberOfCells();
  if (np != reader->GetNumberOfPointsRead() || nc != reader->GetNumberOfTetrahedraRead())
  {
    Violation("output sizes differ from the counts read");
  }
  vtkDataArray* s = ug->GetPointData()->GetArray("scalars");
  if (np > 0 && (!s || s->GetNumberOfTuples() != np))
  {
    Violation("missing or short 'scalars' array");
  }
  if (static_cast<uint64_t>(np + nc) * 8 > size + 1)
  {
    Violation("more points and cells than the input's size allows");
  }
  for (vtkIdType c = 0; c < nc; ++c)
  {
    if (ug->GetCellType(c) != VTK_TETRA)
    {
      Violation("a cell that is not a tetrahedron");
    }
    vtkIdType n;
    const vtkIdType* pts;
    ug->GetCellPoints(c, n, pts);
    if (n != 4)
    {
      Violation("a tetrahedron without 4 points");
    }
    for (int k = 0; k < 4; ++k)
    {
      if (pts[k] < 0 || pts[k] >= np)
      {
        Violation("a point index out of range");
      }
    }
  }
  return 0;
}
