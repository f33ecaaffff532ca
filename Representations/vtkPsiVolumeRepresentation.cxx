#include "vtkPsiVolumeRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkPsiVolumeMapper.h"

namespace
{
constexpr const char* MapperName = "Psi Volume";
}

vtkStandardNewMacro(vtkPsiVolumeRepresentation);

vtkPsiVolumeRepresentation::vtkPsiVolumeRepresentation()
{
  this->AddVolumeMapper(MapperName, this->PsiMapper);
  this->Superclass::SetActiveVolumeMapper(MapperName);
}

vtkPsiVolumeRepresentation::~vtkPsiVolumeRepresentation() = default;

void vtkPsiVolumeRepresentation::SetActiveVolumeMapper(const char*)
{
  this->Superclass::SetActiveVolumeMapper(MapperName);
}

void vtkPsiVolumeRepresentation::SetIntegrationMethod(int method)
{
  if (method != this->PsiMapper->GetIntegrationMethod())
  {
    this->PsiMapper->SetIntegrationMethod(method);
    this->Modified();
  }
}

int vtkPsiVolumeRepresentation::GetIntegrationMethod()
{
  return this->PsiMapper->GetIntegrationMethod();
}

vtkIdType vtkPsiVolumeRepresentation::GetNumberOfTetrahedra()
{
  return this->PsiMapper->GetNumberOfTetrahedra();
}

vtkIdType vtkPsiVolumeRepresentation::GetNumberOfSkippedCells()
{
  return this->PsiMapper->GetNumberOfSkippedCells();
}

double vtkPsiVolumeRepresentation::GetLastRenderSeconds()
{
  return this->PsiMapper->GetLastRenderSeconds();
}

double vtkPsiVolumeRepresentation::GetLastSortSeconds()
{
  return this->PsiMapper->GetLastSortSeconds();
}

vtkPsiVolumeMapper* vtkPsiVolumeRepresentation::GetPsiVolumeMapper()
{
  return this->PsiMapper;
}

void vtkPsiVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->PsiMapper->PrintSelf(os, indent.GetNextIndent());
}
