#include "PsiVolumeLOD.h"

#include "PsiParallel.h"

#include "vtkDataSet.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkObjectFactory.h"

#include <utility>

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// psi::ResampleForLOD and the seconds it took (the build's read-out, LODBuildSeconds).
std::pair<psi::LODImage, double> TimedResample(vtkDataSet* source, const psi::LODArrays& arrays,
  const psi::LODRegion& region, int resolution, bool threaded)
{
  const Clock::time_point t0 = Clock::now();
  psi::LODImage lod = psi::ResampleForLOD(source, arrays, region, resolution, threaded);
  return { std::move(lod), SecondsSince(t0) };
}

// VTK's smart volume mapper (the GPU ray caster where there is one), timed.
class PsiTimedVolumeMapper : public vtkSmartVolumeMapper
{
public:
  static PsiTimedVolumeMapper* New();
  vtkTypeMacro(PsiTimedVolumeMapper, vtkSmartVolumeMapper);
  PsiTimedVolumeMapper()
  {
    // The sample distance given (SetSampleDistance), not one the GPU ray caster derives from the
    // image's size: the smart mapper locks its GPU mapper to the input's spacing, which for a
    // 64^3 image samples every 0.32 spacing, three times the samples of one spacing for no
    // gain in accuracy (docs/decisions.md "Interaction").
    this->GPUMapper->LockSampleDistanceToInputSpacingOff();
    // One ray per 1.5 x 1.5 pixels, the image then magnified: on llvmpipe the ray caster's cost
    // goes with its rays, and at 512^2 this halves the frame on the Blunt Fin with the same
    // error against the exact image (0.668/255 against 0.674 for a ray per pixel; edges blur by
    // about a pixel, docs/decisions.md "Interaction").
    this->GPUMapper->SetImageSampleDistance(1.5f);
  }
  void Render(vtkRenderer* ren, vtkVolume* vol) override
  {
    const Clock::time_point t0 = Clock::now();
    this->Superclass::Render(ren, vol);
    this->LastSeconds = SecondsSince(t0);
  }
  double LastSeconds = 0;
};
vtkStandardNewMacro(PsiTimedVolumeMapper);

} // namespace

PsiVolumeLOD::PsiVolumeLOD()
  : Mapper(vtkSmartPointer<PsiTimedVolumeMapper>::New())
{
  this->Mapper->SetScalarModeToUsePointFieldData();
  // A fixed sample distance (set with each image): the ray caster's own interactive adjustment
  // samples ever more coarsely while the camera moves (its images were 4x further from the
  // exact image on the Blunt Fin, docs/decisions.md "Interaction").
  this->Mapper->SetInteractiveAdjustSampleDistances(0);
  this->Mapper->SetAutoAdjustSampleDistances(0);
  // and no interactive mode of its own: the smart mapper would draw a downsampled copy of the
  // image (its low-resolution GPU mapper) in the renders ParaView marks interactive, which are
  // exactly the renders the level of detail draws
  this->Mapper->SetInteractiveUpdateRate(VTK_FLOAT_MAX);
}

double PsiVolumeLOD::GetLastDrawSeconds() const
{
  return static_cast<PsiTimedVolumeMapper*>(this->Mapper.Get())->LastSeconds;
}

// A build still running is waited for (the future's destructor): it holds only its own copy of
// the piece's structure and arrays.
PsiVolumeLOD::~PsiVolumeLOD() = default;

void PsiVolumeLOD::Reset()
{
  this->Image = nullptr;
  this->Built = Key();
  this->Mapper->RemoveAllInputs();
}

bool PsiVolumeLOD::Key::operator==(const Key& o) const
{
  return Piece == o.Piece && PieceTime == o.PieceTime && BuiltArrays == o.BuiltArrays &&
    BuiltRegion == o.BuiltRegion && Resolution == o.Resolution;
}

PsiVolumeLOD::Key PsiVolumeLOD::KeyOf(
  vtkDataSet* piece, const Arrays& arrays, const Region& region, int resolution)
{
  Key key;
  key.Piece = piece;
  key.PieceTime = piece ? piece->GetMTime() : 0;
  key.BuiltArrays = arrays;
  key.BuiltRegion = region;
  key.Resolution = resolution;
  return key;
}

bool PsiVolumeLOD::Drawable(vtkDataSet* piece, const Arrays& arrays)
{
  return piece && piece->GetNumberOfCells() > 0 && !arrays.Color.empty();
}

bool PsiVolumeLOD::IsCurrent(
  vtkDataSet* piece, const Arrays& arrays, const Region& region, int resolution) const
{
  return this->Image && piece && KeyOf(piece, arrays, region, resolution) == this->Built;
}

bool PsiVolumeLOD::Update(
  vtkDataSet* piece, const Arrays& arrays, const Region& region, int resolution)
{
  if (!Drawable(piece, arrays))
  {
    this->Reset();
    return false;
  }
  if (this->IsCurrent(piece, arrays, region, resolution))
  {
    return false;
  }
  const auto built =
    TimedResample(psi::LODSource(piece, arrays), arrays, region, resolution, true);
  this->Install(built.first, KeyOf(piece, arrays, region, resolution), built.second);
  return true;
}

void PsiVolumeLOD::Request(
  vtkDataSet* piece, const Arrays& arrays, const Region& region, int resolution)
{
  if (!Drawable(piece, arrays))
  {
    this->Reset();
    return;
  }
  if (this->Job || this->IsCurrent(piece, arrays, region, resolution))
  {
    return;
  }
  // The copy is made here, on the main thread; the build reads only the copy. It is marked as
  // background work before its thread starts, so that psi::Parallel leaves vtkSMPTools' backend
  // alone from now until the build ends (PsiParallel.h).
  vtkSmartPointer<vtkDataSet> source = psi::LODSource(piece, arrays);
  source->GetBounds(); // computed and cached here (with the shared points'): the build only reads
  auto mark = std::make_unique<psi::BackgroundWork>();
  this->Job = std::make_unique<Build>();
  this->Job->Inputs = KeyOf(piece, arrays, region, resolution);
  this->Job->Result = std::async(std::launch::async,
    [source, arrays, region, resolution, mark = std::move(mark)]() mutable {
      auto built = TimedResample(source, arrays, region, resolution, false);
      source = nullptr;
      mark.reset();
      return built;
    });
}

bool PsiVolumeLOD::Poll()
{
  if (!this->Job ||
    this->Job->Result.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
  {
    return false;
  }
  const std::pair<psi::LODImage, double> done = this->Job->Result.get();
  const Key inputs = this->Job->Inputs;
  this->Job.reset();
  this->Install(done.first, inputs, done.second);
  return true;
}

void PsiVolumeLOD::Install(const psi::LODImage& lod, const Key& key, double seconds)
{
  this->Image = lod.Image;
  this->Crop(key.BuiltRegion);
  this->Mapper->SetSampleDistance(static_cast<float>(lod.SampleDistance));
  this->Mapper->SetInputData(this->Image);
  this->Mapper->SelectScalarArray(key.BuiltArrays.Color.c_str());
  this->Built = key;
  this->LastBuildSeconds = seconds;
}

// In parallel each process draws only its piece's box: the neighbours' images abut there, as
// ordered compositing requires.
void PsiVolumeLOD::Crop(const Region& region)
{
  this->Mapper->SetCropping(region.Parallel ? 1 : 0);
  if (region.Parallel)
  {
    this->Mapper->SetCroppingRegionPlanes(const_cast<double*>(region.Box));
    this->Mapper->SetCroppingRegionFlagsToSubVolume();
  }
}
