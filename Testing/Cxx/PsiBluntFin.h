// The NASA Blunt Fin from ../shared/data (PLOT3D, big-endian, whole, single grid, no byte counts,
// no IBLANK; see shared/data/MANIFEST.md), read as the structured grid of its single block.
// Shared by the filter tests and benchmarks; nullptr when the files are absent.
#ifndef PsiBluntFin_h
#define PsiBluntFin_h

#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"

#include <fstream>
#include <string>

namespace psitest
{
inline vtkSmartPointer<vtkStructuredGrid> ReadBluntFin(const std::string& dir)
{
  const std::string xyz = dir + "/bluntfinxyz.bin", q = dir + "/bluntfinq.bin";
  if (!std::ifstream(xyz).good() || !std::ifstream(q).good())
  {
    return nullptr;
  }
  vtkNew<vtkMultiBlockPLOT3DReader> reader;
  reader->SetXYZFileName(xyz.c_str());
  reader->SetQFileName(q.c_str());
  reader->BinaryFileOn();
  reader->SetByteOrderToBigEndian();
  reader->MultiGridOff();
  reader->HasByteCountOff();
  reader->IBlankingOff();
  reader->Update();
  return vtkStructuredGrid::SafeDownCast(reader->GetOutput()->GetBlock(0));
}
} // namespace psitest

#endif
