// vtkPsiVolumeMapper's isosurface settings: the raw values are kept for the getters; the list
// drawn is normalized once per change (psi::IsosurfaceList). The rest of the mapper is in
// vtkPsiVolumeMapper.cxx.
#include "vtkPsiVolumeMapper.h"

#include <algorithm>
#include <utility>
#include <vector>

void vtkPsiVolumeMapper::SetIsosurfaceOpacity(double opacity)
{
  opacity = std::min(1.0, std::max(0.0, opacity));
  if (opacity != this->IsosurfaceOpacity)
  {
    this->IsosurfaceOpacity = opacity;
    this->UpdateIsosurfaceList();
    this->Modified();
  }
}

void vtkPsiVolumeMapper::UpdateIsosurfaceList()
{
  this->Isosurfaces = psi::IsosurfaceList::Normalize(
    this->IsosurfaceValues, this->IsosurfaceOpacities, this->IsosurfaceOpacity);
  if (this->Isosurfaces.Dropped)
  {
    vtkWarningMacro("Psi Volume draws at most " << MaxIsosurfaces << " isosurfaces; "
                                                << this->Isosurfaces.Dropped << " ignored.");
  }
}

void vtkPsiVolumeMapper::SetIsosurfaceVector(std::vector<double>& member, std::vector<double> v)
{
  if (v != member)
  {
    member = std::move(v);
    this->UpdateIsosurfaceList();
    this->Modified();
  }
}

void vtkPsiVolumeMapper::SetNumberOfIsosurfaces(int n)
{
  std::vector<double> v = this->IsosurfaceValues;
  v.resize(std::max(n, 0), 0.0);
  this->SetIsosurfaceVector(this->IsosurfaceValues, std::move(v));
}

void vtkPsiVolumeMapper::SetIsosurfaceValue(int i, double value)
{
  if (i < 0)
  {
    return;
  }
  std::vector<double> v = this->IsosurfaceValues;
  v.resize(std::max<size_t>(v.size(), i + 1), 0.0);
  v[i] = value;
  this->SetIsosurfaceVector(this->IsosurfaceValues, std::move(v));
}

void vtkPsiVolumeMapper::SetIsosurfaceValues(const std::vector<double>& values)
{
  this->SetIsosurfaceVector(this->IsosurfaceValues, values);
}

double vtkPsiVolumeMapper::GetIsosurfaceValue(int i) const
{
  return i >= 0 && static_cast<size_t>(i) < this->IsosurfaceValues.size()
    ? this->IsosurfaceValues[i]
    : 0.0;
}

void vtkPsiVolumeMapper::SetNumberOfIsosurfaceOpacities(int n)
{
  std::vector<double> v = this->IsosurfaceOpacities;
  v.resize(std::max(n, 0), this->IsosurfaceOpacity);
  this->SetIsosurfaceVector(this->IsosurfaceOpacities, std::move(v));
}

void vtkPsiVolumeMapper::SetIsosurfaceOpacityValue(int i, double opacity)
{
  if (i < 0)
  {
    return;
  }
  std::vector<double> v = this->IsosurfaceOpacities;
  v.resize(std::max<size_t>(v.size(), i + 1), this->IsosurfaceOpacity);
  v[i] = opacity;
  this->SetIsosurfaceVector(this->IsosurfaceOpacities, std::move(v));
}

void vtkPsiVolumeMapper::SetIsosurfaceOpacities(const std::vector<double>& opacities)
{
  this->SetIsosurfaceVector(this->IsosurfaceOpacities, opacities);
}
