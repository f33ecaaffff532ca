// PsiLODImage: the image the interactive level of detail of 'Psi Volume' draws, made without
// OpenGL: the piece this process draws, probed once on a coarse lattice (VTK's vtkProbeFilter,
// whose validity mask hides the samples outside the mesh, as ParaView's 'Resample To Image'
// does). The image holds scalars, not colors, so a transfer-function edit needs no new image.
// Samples whose scalar is not finite are hidden, as 'Psi Volume' skips the cells that hold one.
//
// In parallel (ordered compositing) every process probes its piece on one lattice, spanned over
// the whole mesh's bounds, and draws only its piece's box of it (PsiVolumeLOD crops the ray
// caster to it): its ray samples are then the serial ray's samples inside that box
// (docs/decisions.md, "Interaction").
//
// ResampleForLOD reads only the source it is given, so it may run on a thread of its own.
#ifndef PsiLODImage_h
#define PsiLODImage_h

#include "PsiVolumeRepresentationsModule.h"

#include "vtkDataSet.h"   // for vtkSmartPointer
#include "vtkImageData.h" // for vtkSmartPointer
#include "vtkSmartPointer.h"

#include <string>

namespace psi
{

/// Samples along each side of the lattice's box (64^3: ParaView's smallest 'Resample To Image').
constexpr int DefaultLODResolution = 64;

/// The arrays the level of detail draws: a point or cell array of the piece (cell arrays become
/// point arrays of the image), and with a separate opacity array, that one too.
struct LODArrays
{
  std::string Color;
  std::string Opacity; ///< "" without a separate opacity array
  bool operator==(const LODArrays& o) const { return Color == o.Color && Opacity == o.Opacity; }
};

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

/// A copy of `piece`'s structure holding only `arrays` (it shares the piece's points, cells and
/// arrays), for ResampleForLOD: the probe resamples every array it is given.
PSIVOLUMEREPRESENTATIONS_EXPORT vtkSmartPointer<vtkDataSet> LODSource(
  vtkDataSet* piece, const LODArrays& arrays);

/// The level of detail's image and the ray caster's sample distance for it.
struct LODImage
{
  vtkSmartPointer<vtkImageData> Image;
  double SampleDistance = 0;
};

/// Probes `source` (from LODSource) on the lattice of `region` (the source's bounds serially)
/// with `resolution` samples along each side, hides the samples outside the mesh and those not
/// finite. `threaded`: the probe on vtkSMPTools' threads (psi::Parallel), else on the calling
/// thread alone.
PSIVOLUMEREPRESENTATIONS_EXPORT LODImage ResampleForLOD(vtkDataSet* source,
  const LODArrays& arrays, const LODRegion& region, int resolution, bool threaded);

} // namespace psi

#endif
