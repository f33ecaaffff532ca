// PsiTransferFunctionAnalysis: what the renderer needs to know about a transfer function beyond
// its sampled table (GL-free): its exact value at a scalar and where its opacity is zero (early
// discard, Maximo et al. 2010 §3.5); its nodes for adaptive sampling are PsiTransferFunctionNodes.
#ifndef PsiTransferFunctionAnalysis_h
#define PsiTransferFunctionAnalysis_h

#include "PsiTetMesh.h"
#include "PsiVolumeCoreModule.h"

#include <string>
#include <vector>

class vtkVolumeProperty;

namespace psi
{
struct TransferFunctionTable;

/// Color (rgb) and opacity of component 0 of `property` at scalar s, from the functions
/// themselves (not a table).
PSIVOLUMECORE_EXPORT void EvaluateTransferFunction(
  vtkVolumeProperty* property, double s, double rgba[4]);

/// The scalar of a tuple of `numberOfComponents` that the color map's vector mode selects, as
/// ParaView's 'Volume' maps it (vtkScalarsToColors: VectorMode Component selects
/// VectorComponent, any other mode the magnitude); component 0 of a one-component array. Two
/// dependent components (IndependentComponents off: ParaView's combined color + opacity array
/// of UseSeparateOpacityArray) are a color scalar and a separate opacity scalar (Opacity = 1).
PSIVOLUMECORE_EXPORT ScalarComponent ColorMapComponent(
  vtkVolumeProperty* property, int numberOfComponents);

/// Why the opacity unit distance (ScalarOpacityUnitDistance of component 0) gives no optical
/// depth: tau = opacity / unit distance needs a positive, finite distance. "" when it is fine.
PSIVOLUMECORE_EXPORT std::string UnitDistanceProblem(vtkVolumeProperty* property);

/// Prefix counts of the table's samples with non-zero opacity: entry i counts samples 0..i. A
/// scalar interval meets only zero-opacity samples when the counts at its ends are equal
/// (Maximo et al. 2010 §3.5). With `property`, a sample also counts when an opacity control
/// point above zero lies between it and the next one, so that a spike narrower than the sample
/// spacing is not discarded. `hasZeroOpacity` tells whether there is a zero region at all.
PSIVOLUMECORE_EXPORT std::vector<float> OpacityPrefixCounts(
  const TransferFunctionTable& table, vtkVolumeProperty* property, bool& hasZeroOpacity);

/// The largest opacity a ray of length `rayLength` through the volume can reach with the table:
/// alpha = 1 - exp(-integral of tau) (Moreland's dissertation Eq. 2.2 with no light behind),
/// at most 1 - exp(-max tau * rayLength). Whether a pixel can turn opaque at all decides
/// whether front-to-back compositing can stop early (PlanFrame).
PSIVOLUMECORE_EXPORT double MaxRayOpacity(const TransferFunctionTable& table, double rayLength);
} // namespace psi

#endif
