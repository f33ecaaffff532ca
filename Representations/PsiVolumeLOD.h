// PsiVolumeLOD: the interactive level of detail of 'Psi Volume', a volume: the image of
// PsiLODImage (this process's piece probed once on a coarse lattice), drawn by VTK's GPU ray
// caster (vtkSmartVolumeMapper) with the same vtkVolumeProperty, hence the same color map,
// opacity function and unit distance. Each process probes its own piece alone (ParaView's
// vtkPResampleToImage would be collective, and a level of detail chosen by each process's own
// frame time must not wait for the others); in parallel each process draws only its piece's box.
//
// Built once per piece, array, region and resolution, not per camera move nor per
// transfer-function edit: either now (Update), or on a thread of its own (Request), the image
// then replacing the old one at the first Poll after the build is done, so that the camera can
// move meanwhile. docs/decisions.md ("Interaction") has the candidates' figures.
#ifndef PsiVolumeLOD_h
#define PsiVolumeLOD_h

#include "PsiLODImage.h"
#include "PsiVolumeRepresentationsModule.h"

#include "vtkImageData.h" // for vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkSmartVolumeMapper.h" // for vtkSmartPointer

#include <chrono>
#include <future>
#include <memory>

class vtkDataSet;

class PSIVOLUMEREPRESENTATIONS_EXPORT PsiVolumeLOD
{
public:
  PsiVolumeLOD();
  ~PsiVolumeLOD();

  using Arrays = psi::LODArrays;
  using Region = psi::LODRegion;
  static constexpr int DefaultResolution = psi::DefaultLODResolution;

  /// Whether the image was built from this piece (unmodified since), these arrays, this region
  /// and this resolution.
  bool IsCurrent(vtkDataSet* piece, const Arrays& arrays, const Region& region,
    int resolution = DefaultResolution) const;
  /// Resamples `piece` now (on vtkSMPTools' threads) when it, its arrays, the region or the
  /// resolution changed since the last build; true when it rebuilt. A null or empty piece gives
  /// no image (the mapper then has no input).
  bool Update(vtkDataSet* piece, const Arrays& arrays, const Region& region,
    int resolution = DefaultResolution);
  /// Starts resampling `piece` on a thread of its own, unless the image is current or such a
  /// build already runs (a build for older inputs runs to its end first: the next Request after
  /// it starts the new one). A null or empty piece gives no image.
  void Request(vtkDataSet* piece, const Arrays& arrays, const Region& region,
    int resolution = DefaultResolution);
  /// Takes the image of a finished Request; true when the image changed.
  bool Poll();
  /// The mapper that draws the image (its input set by Update or Poll).
  vtkSmartVolumeMapper* GetMapper() const { return this->Mapper; }
  /// Whether there is an image to draw.
  bool HasImage() const { return this->Image != nullptr; }
  /// Seconds the mapper's last Render call took (GL work is asynchronous: the call, not the GPU).
  double GetLastDrawSeconds() const;
  /// Seconds the last build took (0 before the first), on its own thread for a Request.
  double GetLastBuildSeconds() const { return this->LastBuildSeconds; }
  /// Forgets the image (a new build on the next Update or Request).
  void Reset();

private:
  PsiVolumeLOD(const PsiVolumeLOD&) = delete;
  void operator=(const PsiVolumeLOD&) = delete;

  /// What an image was built from.
  struct Key
  {
    const vtkDataSet* Piece = nullptr; ///< identity only, never dereferenced
    vtkMTimeType PieceTime = 0;
    Arrays BuiltArrays;
    Region BuiltRegion;
    int Resolution = 0;
    bool operator==(const Key& o) const;
  };
  static Key KeyOf(vtkDataSet* piece, const Arrays& arrays, const Region& region, int resolution);
  static bool Drawable(vtkDataSet* piece, const Arrays& arrays);
  void Install(const psi::LODImage& lod, const Key& key, double seconds);
  void Crop(const Region& region);

  /// A Request's build on its own thread: its inputs and its result (image and seconds).
  struct Build
  {
    Key Inputs;
    std::future<std::pair<psi::LODImage, double>> Result;
  };

  vtkSmartPointer<vtkSmartVolumeMapper> Mapper; ///< a timed vtkSmartVolumeMapper
  vtkSmartPointer<vtkImageData> Image;
  Key Built;
  std::unique_ptr<Build> Job;
  double LastBuildSeconds = 0;
};

#endif
