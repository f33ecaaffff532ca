#include "vtkPsiVolumeRepresentation.h"

#include "vtkDataSet.h"
#include "vtkVolumeRepresentationPreprocessor.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
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

int vtkPsiVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const int ok = this->Superclass::RequestData(request, inputVector, outputVector);
  vtkDataSet* data = vtkDataSet::SafeDownCast(this->Preprocessor->GetOutputDataObject(0));
  if (!data || data->GetNumberOfCells() == 0)
  {
    this->PsiMapper->ResetStatistics();
  }
  return ok;
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

void vtkPsiVolumeRepresentation::SetSortMethod(int method)
{
  if (method != this->PsiMapper->GetSortMethod())
  {
    this->PsiMapper->SetSortMethod(method);
    this->Modified();
  }
}

int vtkPsiVolumeRepresentation::GetSortMethod()
{
  return this->PsiMapper->GetSortMethod();
}

double vtkPsiVolumeRepresentation::GetLastPreIntegrationSeconds()
{
  return this->PsiMapper->GetLastPreIntegrationSeconds();
}

vtkIdType vtkPsiVolumeRepresentation::GetLastSortCycles()
{
  return this->PsiMapper->GetLastSortCycles();
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
