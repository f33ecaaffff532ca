// PsiLODImage: the image the interactive level of detail of 'Psi Volume' draws, made without
// OpenGL: exactly the tetrahedra and the scalar the full frame draws (psi::GatherTetMesh with the
// mapper's array, association and component), sampled once on a coarse lattice
// (psi::SampleOnLattice); the samples outside the drawn tetrahedra are hidden, as ParaView's
// 'Resample To Image' hides those outside the mesh. Cells the full frame skips (not tetrahedra,
// or a scalar not finite) are skipped here too. The image holds scalars, not colors, so a
// transfer-function edit needs no new image.
//
// In parallel (ordered compositing) every process probes its piece on one lattice, spanned over
// the whole mesh's bounds, and draws only its piece's box of it (PsiLevelOfDetail crops the ray
// caster to it): its ray samples are then the serial ray's samples inside that box
// (docs/decisions.md, "Interaction").
#ifndef PsiLODImage_h
#define PsiLODImage_h

#include "PsiVolumeRepresentationsModule.h"

#include "PsiTetMesh.h" // for psi::ScalarComponent

#include "vtkDataSet.h"   // for vtkSmartPointer
#include "vtkImageData.h" // for vtkSmartPointer
#include "vtkSmartPointer.h"

#include <functional>
#include <string>

class vtkPiecewiseFunction;
class vtkUnstructuredGridVolumeMapper;
class vtkVolumeProperty;

namespace psi
{

/// Samples along each side of the lattice's box (64^3: ParaView's smallest 'Resample To Image').
constexpr int DefaultLODResolution = 64;

/// The scalar the level of detail draws: the full frame's (the array the mapper colors by, with
/// its association: a point and a cell array may share a name), and which value of its tuples
/// (psi::ColorMapComponent: a component, the magnitude, and a separate opacity component).
struct LODScalars
{
  std::string Array; ///< "" when there is nothing to color by
  bool Cells = false;
  ScalarComponent Component;
  bool operator==(const LODScalars& o) const
  {
    return Array == o.Array && Cells == o.Cells && Component.Index == o.Component.Index &&
      Component.Opacity == o.Component.Opacity;
  }
};

/// The scalar `mapper` draws from `piece` with `property`'s color map (its array, association and
/// vector mode).
PSIVOLUMEREPRESENTATIONS_EXPORT LODScalars LODScalarsOf(
  vtkUnstructuredGridVolumeMapper* mapper, vtkVolumeProperty* property, vtkDataSet* piece);

/// The name of the image's array: the scalar, and with a separate opacity array its opacity as a
/// second component (luminance and alpha: the ray caster's dependent components).
constexpr const char* LODArrayName = "PsiLODScalar";

/// Where the lattice lies: spanned over `Global` (the whole mesh's bounds), and this process's
/// share of it, `Box` (the box it draws: its piece's bounds), when `Parallel`. Serially the
/// lattice spans the piece's own bounds and no region is given.
struct LODRegion
{
  bool Parallel = false;
  double Global[6] = { 0, 0, 0, 0, 0, 0 };
  double Box[6] = { 0, 0, 0, 0, 0, 0 };
  bool operator==(const LODRegion& o) const;
};

/// The level of detail's image.
struct LODImage
{
  vtkSmartPointer<vtkImageData> Image;
};

/// Samples the tetrahedra of `piece` (an unstructured grid) that the full frame draws with
/// `scalars` on the lattice of `region` (the piece's bounds serially), `resolution` samples along
/// each side; hides the samples outside them. No image for a piece with nothing to draw.
/// `progress` (if given) hears the fraction done.
PSIVOLUMEREPRESENTATIONS_EXPORT LODImage ResampleForLOD(vtkDataSet* piece,
  const LODScalars& scalars, const LODRegion& region, int resolution,
  const std::function<void(double)>& progress = nullptr);

/// The ray caster's sample distance for a lattice of this spacing and rays along `direction`
/// (any length): one lattice spacing as the ray sees it, 1 / |(d_x / h_x, d_y / h_y, d_z / h_z)|
/// for the unit direction d, i.e. one sample per lattice cell in the metric where the cells are
/// unit cubes. Along an axis that axis's spacing (a thin slab seen across takes as many samples
/// as its lattice has layers, where one mean spacing took one or two); on a cubic lattice the
/// spacing in every direction.
PSIVOLUMEREPRESENTATIONS_EXPORT double LODSampleDistance(
  const double spacing[3], const double direction[3]);

/// The opacity function for VTK's ray caster that draws `opacity` as 'Psi Volume' does. 'Psi
/// Volume' reads an opacity value a as an attenuation of a per unit distance (transmittance
/// exp(-a d / unit) over d, the table of psi::TransferFunctionTable); VTK's ray caster as an
/// opacity per unit distance (1 - (1 - a')^(d / unit)). They agree for a' = 1 - exp(-a): the same
/// at small a, and where a nears 1 the ray caster's would be opaque at once. `out` gets a' at
/// `opacity`'s nodes and at `subdivisions` points between each two (a' is not linear in a).
PSIVOLUMEREPRESENTATIONS_EXPORT void LODOpacityFunction(
  vtkPiecewiseFunction* opacity, vtkPiecewiseFunction* out, int subdivisions = 8);

/// A copy of `property` whose (first) scalar opacity function is LODOpacityFunction's.
PSIVOLUMEREPRESENTATIONS_EXPORT void LODVolumeProperty(
  vtkVolumeProperty* property, vtkVolumeProperty* out);

} // namespace psi

#endif
