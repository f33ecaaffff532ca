// vtkPsiVolumeMapper's isosurface settings: the raw values are kept for the getters; the list
// drawn is normalized once per change (psi::IsosurfaceList). The rest of the mapper is in
// vtkPsiVolumeMapper.cxx.
#include "vtkPsiVolumeMapper.h"

#include <algorithm>
#include <utility>
#include <vector>

void vtkPsiVolumeMapper::SetIsosurfaceColor(double r, double g, double b)
{
  double* c = this->Settings.IsosurfaceColor;
  if (c[0] != r || c[1] != g || c[2] != b)
  {
    c[0] = r;
    c[1] = g;
    c[2] = b;
    this->Modified();
  }
}

void vtkPsiVolumeMapper::UpdateIsosurfaceList()
{
  this->Isosurfaces = this->Settings.Isosurfaces();
  if (this->Isosurfaces.Dropped)
  {
    vtkWarningMacro("Psi Volume draws at most " << psi::IsosurfaceList::MaxCount << " isosurfaces; "
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
  std::vector<double> v = this->Settings.IsosurfaceValues;
  v.resize(std::max(n, 0), 0.0);
  this->SetIsosurfaceVector(this->Settings.IsosurfaceValues, std::move(v));
}

void vtkPsiVolumeMapper::SetIsosurfaceValue(int i, double value)
{
  if (i < 0)
  {
    return;
  }
  std::vector<double> v = this->Settings.IsosurfaceValues;
  v.resize(std::max<size_t>(v.size(), i + 1), 0.0);
  v[i] = value;
  this->SetIsosurfaceVector(this->Settings.IsosurfaceValues, std::move(v));
}

void vtkPsiVolumeMapper::SetIsosurfaceValues(const std::vector<double>& values)
{
  this->SetIsosurfaceVector(this->Settings.IsosurfaceValues, values);
}

double vtkPsiVolumeMapper::GetIsosurfaceValue(int i) const
{
  return i >= 0 && static_cast<size_t>(i) < this->Settings.IsosurfaceValues.size()
    ? this->Settings.IsosurfaceValues[i]
    : 0.0;
}

void vtkPsiVolumeMapper::SetNumberOfIsosurfaceOpacities(int n)
{
  std::vector<double> v = this->Settings.IsosurfaceOpacities;
  v.resize(std::max(n, 0), this->Settings.IsosurfaceOpacity);
  this->SetIsosurfaceVector(this->Settings.IsosurfaceOpacities, std::move(v));
}

void vtkPsiVolumeMapper::SetIsosurfaceOpacityValue(int i, double opacity)
{
  if (i < 0)
  {
    return;
  }
  std::vector<double> v = this->Settings.IsosurfaceOpacities;
  v.resize(std::max<size_t>(v.size(), i + 1), this->Settings.IsosurfaceOpacity);
  v[i] = opacity;
  this->SetIsosurfaceVector(this->Settings.IsosurfaceOpacities, std::move(v));
}

void vtkPsiVolumeMapper::SetIsosurfaceOpacities(const std::vector<double>& opacities)
{
  this->SetIsosurfaceVector(this->Settings.IsosurfaceOpacities, opacities);
}
