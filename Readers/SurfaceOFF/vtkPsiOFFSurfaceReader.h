/**
 * @class   vtkPsiOFFSurfaceReader
 * @brief   VTK's polygonal OFF reader, declining the tetrahedral OFF meshes that
 *          vtkPsiOFFTetReader reads.
 *
 * ParaView (5.13 and later) asks each reader that claims a file's extension whether it can read
 * the file (CanReadFile) and shows a dialog when more than one says yes. vtkOFFReader has no
 * CanReadFile, so it says yes to every .off file. This subclass answers for it: yes exactly when
 * vtkPsiOFFTetReader says no. The plugin's XML (XML/PsiVolumeSurfaceOFF.xml) puts it behind
 * ParaView's own "offreader" proxy, with the same name and properties, so state files and scripts
 * that use that reader are unchanged.
 */
#ifndef vtkPsiOFFSurfaceReader_h
#define vtkPsiOFFSurfaceReader_h

#include "PsiVolumeReadersSurfaceOFFModule.h"
#include "vtkOFFReader.h"

class PSIVOLUMEREADERSSURFACEOFF_EXPORT vtkPsiOFFSurfaceReader : public vtkOFFReader
{
public:
  static vtkPsiOFFSurfaceReader* New();
  vtkTypeMacro(vtkPsiOFFSurfaceReader, vtkOFFReader);

  /// 1 for a readable file that is not a tetrahedral OFF mesh, 0 otherwise.
  virtual int CanReadFile(const char* filename);

protected:
  vtkPsiOFFSurfaceReader() = default;
  ~vtkPsiOFFSurfaceReader() override = default;

private:
  vtkPsiOFFSurfaceReader(const vtkPsiOFFSurfaceReader&) = delete;
  void operator=(const vtkPsiOFFSurfaceReader&) = delete;
};

#endif
