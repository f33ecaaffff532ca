#include "vtkPsiVolumeRepresentation.h"

#include "PsiIntegrationMethods.h"

#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPsiConformingTetrahedralize.h"
#include "vtkPsiVolumeMapper.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeRepresentationPreprocessor.h"

#include <algorithm>

namespace
{
constexpr const char* MapperName = "Psi Volume";

// An integer setting outside its values (possible through the server manager, which does not
// check enumeration domains) is clamped, with a warning that names it.
int InRange(vtkObject* self, const char* name, int value, int lo, int hi)
{
  if (value >= lo && value <= hi)
  {
    return value;
  }
  const int used = value < lo ? lo : hi;
  vtkWarningWithObjectMacro(self, "'Psi Volume' " << name << " = " << value
                                                  << " is not one of its values (" << lo
                                                  << " to " << hi << "): " << used
                                                  << " is used.");
  return used;
}

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

void vtkPsiVolumeRepresentation::SetIntegrationMethod(int method)
{
  method = InRange(this, "IntegrationMethod", method, 0, psi::NumberOfIntegrationMethods() - 1);
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

void vtkPsiVolumeRepresentation::SetEarlyDiscard(bool on)
{
  if (on != this->PsiMapper->GetEarlyDiscard())
  {
    this->PsiMapper->SetEarlyDiscard(on);
    this->Modified();
  }
}

bool vtkPsiVolumeRepresentation::GetEarlyDiscard()
{
  return this->PsiMapper->GetEarlyDiscard();
}

void vtkPsiVolumeRepresentation::SetSortMethod(int method)
{
  method = InRange(this, "SortMethod", method, vtkPsiVolumeMapper::CENTROID,
    vtkPsiVolumeMapper::MPVONC);
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

void vtkPsiVolumeRepresentation::SetProjector(int projector)
{
  projector = InRange(this, "Projector", projector, vtkPsiVolumeMapper::PROJECTOR_GEOMETRY_SHADER,
    vtkPsiVolumeMapper::PROJECTOR_AUTO);
  if (projector != this->PsiMapper->GetProjector())
  {
    this->PsiMapper->SetProjector(projector);
    this->Modified();
  }
}

int vtkPsiVolumeRepresentation::GetProjector()
{
  return this->PsiMapper->GetProjector();
}

void vtkPsiVolumeRepresentation::SetDecomposition(int decomposition)
{
  decomposition = InRange(this, "Decomposition", decomposition,
    vtkPsiVolumeMapper::DECOMPOSITION_SILHOUETTE, vtkPsiVolumeMapper::DECOMPOSITION_AUTO);
  if (decomposition != this->PsiMapper->GetDecomposition())
  {
    this->PsiMapper->SetDecomposition(decomposition);
    this->Modified();
  }
}

int vtkPsiVolumeRepresentation::GetDecomposition()
{
  return this->PsiMapper->GetDecomposition();
}

void vtkPsiVolumeRepresentation::SetNumberOfIsosurfaces(int n)
{
  if (n != this->PsiMapper->GetNumberOfIsosurfaces())
  {
    this->PsiMapper->SetNumberOfIsosurfaces(n);
    this->Modified();
  }
}

void vtkPsiVolumeRepresentation::SetIsosurfaceValue(int i, double value)
{
  if (i >= this->PsiMapper->GetNumberOfIsosurfaces() ||
    this->PsiMapper->GetIsosurfaceValue(i) != value)
  {
    this->PsiMapper->SetIsosurfaceValue(i, value);
    this->Modified();
  }
}

void vtkPsiVolumeRepresentation::SetIsosurfaceOpacity(double opacity)
{
  if (opacity != this->PsiMapper->GetIsosurfaceOpacity())
  {
    this->PsiMapper->SetIsosurfaceOpacity(opacity);
    this->Modified();
  }
}

void vtkPsiVolumeRepresentation::SetNumberOfIsosurfaceOpacities(int n)
{
  if (static_cast<size_t>(std::max(0, n)) != this->PsiMapper->GetIsosurfaceOpacities().size())
  {
    this->PsiMapper->SetNumberOfIsosurfaceOpacities(n);
    this->Modified();
  }
}

void vtkPsiVolumeRepresentation::SetIsosurfaceOpacityValue(int i, double opacity)
{
  const std::vector<double>& o = this->PsiMapper->GetIsosurfaceOpacities();
  if (i < 0 || static_cast<size_t>(i) >= o.size() || o[i] != opacity)
  {
    this->PsiMapper->SetIsosurfaceOpacityValue(i, opacity);
    this->Modified();
  }
}

void vtkPsiVolumeRepresentation::SetIsosurfaceColor(double r, double g, double b)
{
  this->PsiMapper->SetIsosurfaceColor(r, g, b);
  this->Modified();
}

void vtkPsiVolumeRepresentation::SetIsosurfaceUseColorMap(int on)
{
  if ((on != 0) != this->PsiMapper->GetIsosurfaceUseColorMap())
  {
    this->PsiMapper->SetIsosurfaceUseColorMap(on != 0);
    this->Modified();
  }
}

void vtkPsiVolumeRepresentation::SetIsosurfaceShading(int shading)
{
  shading = InRange(this, "IsosurfaceShading", shading, 0, 2);
  const bool lit = shading != 2;
  const int mode =
    shading == 1 ? vtkPsiVolumeMapper::ISO_FLAT : vtkPsiVolumeMapper::ISO_SMOOTH;
  if (lit != this->PsiMapper->GetIsosurfaceLighting() ||
    mode != this->PsiMapper->GetIsosurfaceShading())
  {
    this->PsiMapper->SetIsosurfaceLighting(lit);
    this->PsiMapper->SetIsosurfaceShading(mode);
    this->Modified();
  }
}

void vtkPsiVolumeRepresentation::SetIsosurfaceMethod(int method)
{
  method = InRange(this, "IsosurfaceMethod", method, vtkPsiVolumeMapper::ISO_MARCHING_TETRAHEDRA,
    vtkPsiVolumeMapper::ISO_AUTO);
  if (method != this->PsiMapper->GetIsosurfaceMethod())
  {
    this->PsiMapper->SetIsosurfaceMethod(method);
    this->Modified();
  }
}

int vtkPsiVolumeRepresentation::GetLastUsedIsosurfaceMethod()
{
  return this->PsiMapper->GetLastUsedIsosurfaceMethod();
}

int vtkPsiVolumeRepresentation::GetLastNumberOfAdaptiveNodes()
{
  return this->PsiMapper->GetLastNumberOfAdaptiveNodes();
}

void vtkPsiVolumeRepresentation::SetAdaptiveSampling(int mode)
{
  mode = InRange(this, "AdaptiveSampling", mode, vtkPsiVolumeMapper::ADAPTIVE_OFF,
    vtkPsiVolumeMapper::ADAPTIVE_AUTO);
  if (mode != this->PsiMapper->GetAdaptiveSampling())
  {
    this->PsiMapper->SetAdaptiveSampling(mode);
    this->Modified();
  }
}

int vtkPsiVolumeRepresentation::GetAdaptiveSampling()
{
  return this->PsiMapper->GetAdaptiveSampling();
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
  this->PsiMapper->PrintSelf(os, indent.GetNextIndent());
}
