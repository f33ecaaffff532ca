// PsiTransferFunctionTable: samples a ParaView color map and opacity function into one RGBA
// float table over a scalar range: rgb = luminance L(s), a = attenuation tau(s).
//
// tau = opacity / ScalarOpacityUnitDistance, the convention of VTK's unstructured-grid ray
// integrators (vtkUnstructuredGridLinearRayIntegrator::GetTransferFunction), so that 'Psi Volume'
// and ParaView's 'Volume' agree on what an opacity function means.
#ifndef PsiTransferFunctionTable_h
#define PsiTransferFunctionTable_h

#include "PsiVolumeCoreModule.h"

#include <vector>

class vtkVolumeProperty;

namespace psi
{

struct PSIVOLUMECORE_EXPORT TransferFunctionTable
{
  double Range[2] = { 0, 1 }; ///< scalar at the first and the last sample
  /// Opacity scalar at the first and the last sample of the attenuation (a): Range, or with a
  /// separate opacity array the range of the opacity scalars.
  double OpacityRange[2] = { 0, 1 };
  int Size = 0;
  std::vector<float> Rgba; ///< Size * 4 values: L.r, L.g, L.b, tau

  /// Linear interpolation at scalar s (clamped at the ends), as the GPU's linear filter does.
  void Lookup(double s, double out[4]) const;
};

/// ScalarOpacityUnitDistance of component 0, at least 1e-30: tau = opacity / this distance (a
/// distance of 0 or less draws nothing at all: psi::UnitDistanceProblem).
PSIVOLUMECORE_EXPORT double OpacityUnitDistance(vtkVolumeProperty* property);

/// Samples component 0 of `property` at `size` evenly spaced scalars over `range`; with
/// `opacityRange` (a separate opacity array) the attenuation over that range instead.
PSIVOLUMECORE_EXPORT TransferFunctionTable SampleTransferFunction(vtkVolumeProperty* property,
  const double range[2], int size, const double* opacityRange = nullptr);

} // namespace psi

#endif
