#include "vtkPsiVolumeRepresentation.h"

#include "PsiLODVolume.h"
#include "PsiLevelOfDetail.h"

#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPVLogger.h"
#include "vtkPolyDataMapper.h"
#include "vtkPsiConformingTetrahedralize.h"
#include "vtkPsiVolumeMapper.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeRepresentationPreprocessor.h"

namespace
{
constexpr const char* MapperName = "Psi Volume";

// Whether `data` has cells other than tetrahedra (every dataset but an all-tetrahedra
// unstructured grid; an empty one has nothing to split).
bool HasNonTetrahedra(vtkDataSet* data)
{
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid)
  {
    return data->GetNumberOfCells() > 0;
  }
  vtkUnsignedCharArray* types = grid->GetDistinctCellTypesArray();
  for (vtkIdType i = 0; types && i < types->GetNumberOfValues(); ++i)
  {
    if (types->GetValue(i) != VTK_TETRA)
    {
      return true;
    }
  }
  return false;
}
}

vtkStandardNewMacro(vtkPsiVolumeRepresentation);

vtkPsiVolumeRepresentation::vtkPsiVolumeRepresentation()
  : LOD(new PsiLevelOfDetail)
{
  // the actor whose low level of detail may be a volume (PsiLODVolume)
  vtkNew<PsiLODVolume> actor;
  actor->SetProperty(this->Property);
  actor->SetLODMapper(this->LODMapper.GetPointer());
  actor->SetVisibility(this->Actor->GetVisibility());
  this->Actor = actor;
  // the frame's stages logged at ParaView's rendering verbosity (--verbosity)
  this->PsiMapper->SetLogVerbosity(PARAVIEW_LOG_RENDERING_VERBOSITY());
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
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  this->TetrahedralizeInput = input && HasNonTetrahedra(input); // see GetInternalOutputPort
  const int ok = this->Superclass::RequestData(request, inputVector, outputVector);
  vtkDataSet* data = vtkDataSet::SafeDownCast(this->Preprocessor->GetOutputDataObject(0));
  if (!data || data->GetNumberOfCells() == 0)
  {
    this->PsiMapper->ResetStatistics();
  }
  return ok;
}

// The superclass feeds its preprocessor (VTK's generic triangulator) from this port: for
// non-tetrahedral input it gets the conforming tetrahedralization instead, whose all-tetrahedra
// output the preprocessor passes through.
vtkAlgorithmOutput* vtkPsiVolumeRepresentation::GetInternalOutputPort(int port, int conn)
{
  vtkAlgorithmOutput* input = this->Superclass::GetInternalOutputPort(port, conn);
  if (port != 0 || conn != 0 || !this->TetrahedralizeInput)
  {
    return input;
  }
  this->Conforming->SetInputConnection(input);
  return this->Conforming->GetOutputPort();
}

// Each property goes to the mapper as it is: the mapper holds the settings and clamps them
// (psi::SetClamped). The representation is modified when the mapper is.
template <typename Setter, typename... Values>
void vtkPsiVolumeRepresentation::Forward(Setter set, Values... values)
{
  const vtkMTimeType before = this->PsiMapper->GetMTime();
  (this->PsiMapper.GetPointer()->*set)(values...);
  if (this->PsiMapper->GetMTime() != before)
  {
    this->Modified();
  }
}

// The setters of PSI_RENDER_SETTINGS forward to the mapper, whose clamp warns once.
#define PSI_FORWARD_ENUM(Name, Type, Default, Last)                                                \
  void vtkPsiVolumeRepresentation::Set##Name(int value)                                            \
  {                                                                                                \
    using NumberSetter = void (vtkPsiVolumeMapper::*)(int);                                        \
    this->Forward(static_cast<NumberSetter>(&vtkPsiVolumeMapper::Set##Name), value);               \
  }
#define PSI_FORWARD_NUMBER(Name, Type, Default, Min, Max, Where)                                   \
  void vtkPsiVolumeRepresentation::Set##Name(Type value)                                           \
  {                                                                                                \
    this->Forward(&vtkPsiVolumeMapper::Set##Name, value);                                          \
  }
#define PSI_FORWARD_BOOL(Name, Default, Where)                                                     \
  void vtkPsiVolumeRepresentation::Set##Name(int on)                                               \
  {                                                                                                \
    this->Forward(&vtkPsiVolumeMapper::Set##Name, on != 0);                                        \
  }
PSI_RENDER_SETTINGS(PSI_FORWARD_ENUM, PSI_FORWARD_NUMBER, PSI_FORWARD_BOOL)

// The setters of PSI_INTERACTION_SETTINGS set the representation's own.
#define PSI_INTERACTION_ENUM(Name, Type, Default, Last)                                            \
  void vtkPsiVolumeRepresentation::Set##Name(int value)                                            \
  {                                                                                                \
    this->SetInteraction(psi::Setting::Name, value);                                               \
  }
#define PSI_INTERACTION_NUMBER(Name, Type, Default, Min, Max, Where)                               \
  void vtkPsiVolumeRepresentation::Set##Name(Type value)                                           \
  {                                                                                                \
    this->SetInteraction(psi::Setting::Name, value);                                               \
  }
#define PSI_INTERACTION_BOOL(Name, Default, Where)                                                 \
  void vtkPsiVolumeRepresentation::Set##Name(int on)                                               \
  {                                                                                                \
    this->SetInteraction(psi::Setting::Name, on);                                                  \
  }
PSI_INTERACTION_SETTINGS(PSI_INTERACTION_ENUM, PSI_INTERACTION_NUMBER, PSI_INTERACTION_BOOL)

// The one clamp of an interaction setting, with its one warning (psi::SetClamped).
void vtkPsiVolumeRepresentation::SetInteraction(psi::Setting id, double value)
{
  const psi::SettingChange change = psi::Change(this->Interaction, id, value);
  if (!change.Warning.empty())
  {
    vtkWarningMacro(<< change.Warning);
  }
  if (change.Changed)
  {
    this->Modified();
  }
}

void vtkPsiVolumeRepresentation::SetNumberOfIsosurfaces(int n)
{
  this->Forward(&vtkPsiVolumeMapper::SetNumberOfIsosurfaces, n);
}

void vtkPsiVolumeRepresentation::SetIsosurfaceValue(int i, double value)
{
  this->Forward(&vtkPsiVolumeMapper::SetIsosurfaceValue, i, value);
}

void vtkPsiVolumeRepresentation::SetNumberOfIsosurfaceOpacities(int n)
{
  this->Forward(&vtkPsiVolumeMapper::SetNumberOfIsosurfaceOpacities, n);
}

void vtkPsiVolumeRepresentation::SetIsosurfaceOpacityValue(int i, double opacity)
{
  this->Forward(&vtkPsiVolumeMapper::SetIsosurfaceOpacityValue, i, opacity);
}

void vtkPsiVolumeRepresentation::SetIsosurfaceColor(double r, double g, double b)
{
  this->Forward(&vtkPsiVolumeMapper::SetIsosurfaceColor, r, g, b);
}

int vtkPsiVolumeRepresentation::GetLastUsedIsosurfaceMethod()
{
  return this->PsiMapper->GetLastUsedIsosurfaceMethod();
}

int vtkPsiVolumeRepresentation::GetLastNumberOfAdaptiveNodes()
{
  return this->PsiMapper->GetLastNumberOfAdaptiveNodes();
}

double vtkPsiVolumeRepresentation::GetLastPreIntegrationSeconds()
{
  return this->PsiMapper->GetLastPreIntegrationSeconds();
}

vtkIdType vtkPsiVolumeRepresentation::GetLastSortCycles()
{
  return this->PsiMapper->GetLastSortCycles();
}

vtkIdType vtkPsiVolumeRepresentation::GetNumberOfIntermixedVolumes()
{
  return this->PsiMapper->GetNumberOfIntermixedVolumes();
}

vtkIdType vtkPsiVolumeRepresentation::GetNumberOfIntermixedTetrahedra()
{
  return this->PsiMapper->GetNumberOfIntermixedTetrahedra();
}

const char* vtkPsiVolumeRepresentation::GetLastDrawWay()
{
  return this->PsiMapper->GetLastDrawWay().c_str();
}

vtkIdType vtkPsiVolumeRepresentation::GetNumberOfTetrahedra()
{
  return this->PsiMapper->GetNumberOfTetrahedra();
}

vtkIdType vtkPsiVolumeRepresentation::GetNumberOfSkippedCells()
{
  return this->GetFrameStats().NumberOfSkippedCells;
}

double vtkPsiVolumeRepresentation::GetLastRenderSeconds()
{
  return this->PsiMapper->GetLastRenderSeconds();
}

double vtkPsiVolumeRepresentation::GetLastSortSeconds()
{
  return this->PsiMapper->GetLastSortSeconds();
}

psi::FrameStats vtkPsiVolumeRepresentation::GetFrameStats() const
{
  psi::FrameStats stats = this->PsiMapper->GetFrameStats();
  if (this->TetrahedralizeInput) // cells the tetrahedralization could not split (2D, ...)
  {
    stats.NumberOfSkippedCells += this->Conforming->GetNumberOfSkippedCells();
  }
  return stats;
}

void vtkPsiVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const psi::SettingInfo& info : psi::SettingTable())
  {
    if (info.Interaction)
    {
      os << indent << info.Name << ": " << psi::ValueOf(this->Interaction, info.Id) << "\n";
    }
  }
  this->PsiMapper->PrintSelf(os, indent.GetNextIndent());
}
