// PsiVolumeLOD: the interactive level of detail of 'Psi Volume', a volume: the piece this process
// draws, probed once on a coarse lattice (VTK's vtkProbeFilter, whose validity mask hides the
// samples outside the mesh, as ParaView's 'Resample To Image' does) and drawn by VTK's GPU ray
// caster (vtkSmartVolumeMapper) with the same vtkVolumeProperty, hence the same color map,
// opacity function and unit distance. Each process probes its own piece alone (vtkResampleToImage
// would be ParaView's collective vtkPResampleToImage, and a level of detail chosen by each
// process's own frame time must not wait for the others). In parallel (ordered compositing) every
// process probes its piece on one lattice, spanned over the whole mesh's bounds, and draws only its
// own region of it (its piece's box, through the mapper's cropping): its ray samples are then the
// serial ray's samples inside that box, and the composited image is the serial one up to the 8-bit
// compositing of the processes' images (docs/decisions.md, "Interaction").
//
// Built once per piece, array and resolution, not per camera move nor per transfer-function edit
// (the image holds scalars, not colors). Samples whose scalar is not finite are blanked, as
// 'Psi Volume' skips the cells that hold one. docs/decisions.md ("Interaction") has the
// candidates' figures.
#ifndef PsiVolumeLOD_h
#define PsiVolumeLOD_h

#include "PsiVolumeRepresentationsModule.h"

#include "vtkImageData.h"        // for vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkSmartVolumeMapper.h" // for vtkSmartPointer

#include <string>

class vtkDataSet;

class PSIVOLUMEREPRESENTATIONS_EXPORT PsiVolumeLOD
{
public:
  PsiVolumeLOD();
  ~PsiVolumeLOD();

  /// Samples along each side of the lattice's box (64^3: ParaView's smallest 'Resample To Image').
  static constexpr int DefaultResolution = 64;

  /// The array the level of detail draws: a point or cell array of the piece (cell arrays become
  /// point arrays of the image), and with a separate opacity array, that one too.
  struct Arrays
  {
    std::string Color;
    std::string Opacity; ///< "" without a separate opacity array
    bool operator==(const Arrays& o) const { return Color == o.Color && Opacity == o.Opacity; }
  };

  /// Where the lattice lies: spanned over `Global` (the whole mesh's bounds), and this process's
  /// share of it, `Cut` (the box it draws: its piece's bounds), when `Parallel`. Serially the
  /// lattice spans the piece's own bounds and no region is given.
  struct Region
  {
    bool Parallel = false;
    double Global[6] = { 0, 0, 0, 0, 0, 0 };
    double Cut[6] = { 0, 0, 0, 0, 0, 0 };
    bool operator==(const Region& o) const;
  };

  /// Whether the image was built from this piece (unmodified since), these arrays, this region
  /// and this resolution.
  bool IsCurrent(vtkDataSet* piece, const Arrays& arrays, const Region& region,
    int resolution = DefaultResolution) const;
  /// Resamples `piece` when it, its arrays, the region or the resolution changed since the last
  /// build; true when it rebuilt. A null or empty piece gives no image (the mapper then has no
  /// input).
  bool Update(vtkDataSet* piece, const Arrays& arrays, const Region& region,
    int resolution = DefaultResolution);
  /// The mapper that draws the image (its input set by Update).
  vtkSmartVolumeMapper* GetMapper() const { return this->Mapper; }
  /// Whether there is an image to draw.
  bool HasImage() const { return this->Image != nullptr; }
  /// Seconds the mapper's last Render call took (GL work is asynchronous: the call, not the GPU).
  double GetLastDrawSeconds() const;
  /// Seconds the last build took (0 before the first).
  double GetLastBuildSeconds() const { return this->LastBuildSeconds; }
  /// Forgets the image (a new build on the next Update).
  void Reset();

private:
  PsiVolumeLOD(const PsiVolumeLOD&) = delete;
  void operator=(const PsiVolumeLOD&) = delete;
  void Crop(const Region& region);

  vtkSmartPointer<vtkSmartVolumeMapper> Mapper; ///< a timed vtkSmartVolumeMapper
  vtkSmartPointer<vtkImageData> Image;
  vtkDataSet* Piece = nullptr; ///< identity only, never dereferenced after Update
  unsigned long PieceTime = 0;
  Arrays BuiltArrays;
  Region BuiltRegion;
  int BuiltResolution = 0;
  double LastBuildSeconds = 0;
};

#endif
