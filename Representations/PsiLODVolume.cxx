#include "PsiLODVolume.h"

#include "PsiLODImage.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkLODProp3D.h"
#include "vtkObjectFactory.h"
#include "vtkVolumeProperty.h"

vtkStandardNewMacro(PsiLODVolume);

bool PsiLODVolume::LowLODIsVolume()
{
  return this->GetLowLODVolumeMapper() != nullptr;
}

vtkAbstractVolumeMapper* PsiLODVolume::GetLowLODVolumeMapper()
{
  return this->LowLODId >= 0
    ? vtkAbstractVolumeMapper::SafeDownCast(this->LODProp->GetLODMapper(this->LowLODId))
    : nullptr;
}

bool PsiLODVolume::DrawsVolumeLOD()
{
  vtkAbstractVolumeMapper* mapper = this->GetLowLODVolumeMapper();
  return mapper && this->LODProp->GetSelectedLODID() == this->LowLODId &&
    mapper->GetDataObjectInput() != nullptr;
}

int PsiLODVolume::HasTranslucentPolygonalGeometry()
{
  return this->SelectLOD() == this->LowLODId && !this->LowLODIsVolume() ? 1 : 0;
}

// A volume LOD draws with the volume property's copy (UpdateLowLODVolumeProperty); a surface LOD
// keeps its own.
void PsiLODVolume::UpdateLODProperty()
{
  if (!this->Property)
  {
    return;
  }
  if (this->HighLODId >= 0)
  {
    this->LODProp->SetLODProperty(this->HighLODId, this->Property);
  }
  if (this->LowLODIsVolume())
  {
    this->UpdateLowLODVolumeProperty();
    this->LODProp->SetLODProperty(this->LowLODId, this->LowLODVolumeProperty.Get());
  }
}

void PsiLODVolume::UpdateLowLODVolumeProperty()
{
  if (this->Property && this->Property->GetMTime() > this->LowLODVolumePropertyTime)
  {
    psi::LODVolumeProperty(this->Property, this->LowLODVolumeProperty);
    this->LowLODVolumePropertyTime = this->Property->GetMTime();
  }
}
