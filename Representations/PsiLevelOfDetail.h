// PsiLevelOfDetail: the interactive level of detail of 'Psi Volume', a volume: the image of
// PsiLODImage (this process's piece sampled once on a coarse lattice), drawn by VTK's GPU ray
// caster (vtkSmartVolumeMapper) with the same vtkVolumeProperty, hence the same color map,
// opacity function and unit distance. Each process samples its own piece alone (ParaView's
// vtkPResampleToImage would be collective, and a level of detail chosen by each process's own
// frame time must not wait for the others); in parallel each process draws only its piece's box.
// With several displays in one view, the frame's first call draws every display's image, back to
// front (PsiLODFrames).
//
// Built once per piece, scalar, region and resolution, not per camera move nor per
// transfer-function edit, on the main thread in the first interactive render that needs it: the
// build takes a fraction of a still frame (docs/decisions.md "Interaction" has the figures and
// the build on a thread of its own that it replaced), so no thread outlives a render and no VTK
// object is shared with one.
#ifndef PsiLevelOfDetail_h
#define PsiLevelOfDetail_h

#include "PsiLODImage.h"
#include "PsiVolumeRepresentationsModule.h"

#include "vtkImageData.h" // for vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkSmartVolumeMapper.h" // for vtkSmartPointer

#include <functional>
#include <string>

class vtkDataSet;

class PSIVOLUMEREPRESENTATIONS_EXPORT PsiLevelOfDetail
{
public:
  PsiLevelOfDetail();
  ~PsiLevelOfDetail();

  using Scalars = psi::LODScalars;
  using Region = psi::LODRegion;
  static constexpr int DefaultResolution = psi::DefaultLODResolution;

  /// Whether Update would change anything: a drawable piece whose image was not built from this
  /// piece (unmodified since), scalar, region and resolution, and whose build did not fail for
  /// them; or an image to forget when nothing is drawable.
  bool NeedsUpdate(vtkDataSet* piece, const Scalars& scalars, const Region& region,
    int resolution = DefaultResolution) const;
  /// Resamples `piece` now (on vtkSMPTools' threads) when it, its scalar, the region or the
  /// resolution changed since the last build; true when it rebuilt. A null or empty piece gives
  /// no image (the mapper then has no input). `progress` hears the fraction done. A build that
  /// fails (an exception, e.g. out of memory) leaves no image and gives `Error`, once for those
  /// inputs: the next Update for them does not try again.
  bool Update(vtkDataSet* piece, const Scalars& scalars, const Region& region,
    int resolution = DefaultResolution, const std::function<void(double)>& progress = nullptr);
  /// Samples the image for rays along `direction` (the camera's view direction, any length):
  /// one lattice spacing as the ray sees it (psi::LODSampleDistance).
  void SetViewDirection(const double direction[3]);
  /// Why the last build failed, once: "" when it did not, or when this was already taken.
  std::string TakeNewError();
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
  PsiLevelOfDetail(const PsiLevelOfDetail&) = delete;
  void operator=(const PsiLevelOfDetail&) = delete;

  /// What an image was built from.
  struct Key
  {
    const vtkDataSet* Piece = nullptr; ///< identity only, never dereferenced
    vtkMTimeType PieceTime = 0;
    Scalars BuiltScalars;
    Region BuiltRegion;
    int Resolution = 0;
    bool operator==(const Key& o) const;
  };
  static Key KeyOf(vtkDataSet* piece, const Scalars& scalars, const Region& region, int resolution);
  static bool Drawable(vtkDataSet* piece, const Scalars& scalars);
  void Install(const psi::LODImage& lod, const Key& key, double seconds);
  void Crop(const Region& region);

  vtkSmartPointer<vtkSmartVolumeMapper> Mapper; ///< a timed vtkSmartVolumeMapper
  vtkSmartPointer<vtkImageData> Image;
  Key Built;
  Key Failed; ///< the inputs of the last build that failed
  std::string Error;
  bool ErrorTaken = false;
  double LastBuildSeconds = 0;
};

#endif
