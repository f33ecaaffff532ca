#include "vtkPsiOFFSurfaceReader.h"

#include "vtkObjectFactory.h"
#include "vtkPsiOFFTetReader.h"

#include <fstream>

vtkStandardNewMacro(vtkPsiOFFSurfaceReader);

int vtkPsiOFFSurfaceReader::CanReadFile(const char* filename)
{
  if (!filename || !std::ifstream(filename))
  {
    return 0;
  }
  return vtkPsiOFFTetReader::IsTetrahedralOFF(filename) ? 0 : 1;
}
