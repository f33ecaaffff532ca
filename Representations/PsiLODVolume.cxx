#include "PsiLODVolume.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkLODProp3D.h"
#include "vtkObjectFactory.h"
#include "vtkVolumeProperty.h"

vtkStandardNewMacro(PsiLODVolume);

bool PsiLODVolume::LowLODIsVolume()
{
  return this->LowLODId >= 0 &&
    vtkAbstractVolumeMapper::SafeDownCast(this->LODProp->GetLODMapper(this->LowLODId));
}

int PsiLODVolume::HasTranslucentPolygonalGeometry()
{
  return this->SelectLOD() == this->LowLODId && !this->LowLODIsVolume() ? 1 : 0;
}

// A volume LOD shares the volume property, as the high LOD does; a surface LOD keeps its own.
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
    this->LODProp->SetLODProperty(this->LowLODId, this->Property);
  }
}
