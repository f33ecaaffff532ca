// PsiLODVolume: ParaView's vtkPVLODVolume, for a low level of detail that is a volume. ParaView's
// own class was written for a surface level of detail: it asks the low LOD for a surface mapper
// each time a property or mapper is set (an error logged for a volume mapper) and reports
// translucent polygonal geometry whenever the low LOD is drawn (the renderer then draws the volume
// inside its depth-peeling pass, about a fifth slower). Here both follow the low LOD's kind, and
// a volume low LOD draws with its own copy of the volume property, whose opacity VTK's ray caster
// reads as 'Psi Volume' does (psi::LODVolumeProperty).
#ifndef PsiLODVolume_h
#define PsiLODVolume_h

#include "vtkNew.h" // for vtkNew
#include "vtkPVLODVolume.h"
#include "vtkVolumeProperty.h" // for vtkNew

class PsiLODVolume : public vtkPVLODVolume
{
public:
  static PsiLODVolume* New();
  vtkTypeMacro(PsiLODVolume, vtkPVLODVolume);

  int HasTranslucentPolygonalGeometry() override;
  /// Brings the volume level of detail's property up to date with the volume's (after a
  /// transfer-function edit): a copy whose opacity function draws as 'Psi Volume' reads it
  /// (psi::LODVolumeProperty).
  void UpdateLowLODVolumeProperty();
  /// Whether this frame draws the volume level of detail: the low LOD is selected (in
  /// SetAllocatedRenderTime, before the renderer draws), a volume, with an input to draw.
  bool DrawsVolumeLOD();
  /// The volume level of detail's mapper (nullptr when the low LOD is not a volume).
  vtkAbstractVolumeMapper* GetLowLODVolumeMapper();

protected:
  PsiLODVolume() = default;
  ~PsiLODVolume() override = default;
  void UpdateLODProperty() override;

private:
  PsiLODVolume(const PsiLODVolume&) = delete;
  void operator=(const PsiLODVolume&) = delete;
  bool LowLODIsVolume();
  vtkNew<vtkVolumeProperty> LowLODVolumeProperty;
  vtkMTimeType LowLODVolumePropertyTime = 0;
};

#endif
