#include "PsiLevelOfDetail.h"

#include "PsiLODFrames.h"
#include "PsiStopwatch.h"

#include "vtkDataSet.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkObjectFactory.h"

#include <exception>
#include <utility>

namespace
{

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
  // With several displays drawing their level of detail, the frame's first call draws them all
  // in one visibility order (PsiLODFrames); each display reads out its own draw's time.
  void Render(vtkRenderer* ren, vtkVolume* vol) override
  {
    if (!PsiLODFrames::DrawsAlone(ren, this))
    {
      return;
    }
    const psi::Stopwatch clock;
    this->Superclass::Render(ren, vol);
    this->LastSeconds = clock.Seconds();
  }
  double LastSeconds = 0;
};
vtkStandardNewMacro(PsiTimedVolumeMapper);

} // namespace

PsiLevelOfDetail::PsiLevelOfDetail()
  : Mapper(vtkSmartPointer<PsiTimedVolumeMapper>::New())
{
  // the image's one array: the scalar the full frame draws (a component or the magnitude
  // already taken), with a separate opacity as its second, dependent component
  this->Mapper->SetScalarModeToUsePointFieldData();
  this->Mapper->SelectScalarArray(psi::LODArrayName);
  this->Mapper->SetVectorMode(vtkSmartVolumeMapper::DISABLED);
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

double PsiLevelOfDetail::GetLastDrawSeconds() const
{
  return static_cast<PsiTimedVolumeMapper*>(this->Mapper.Get())->LastSeconds;
}

PsiLevelOfDetail::~PsiLevelOfDetail() = default;

void PsiLevelOfDetail::Reset()
{
  this->Image = nullptr;
  this->Built = Key();
  this->Mapper->RemoveAllInputs();
}

bool PsiLevelOfDetail::Key::operator==(const Key& o) const
{
  return Piece == o.Piece && PieceTime == o.PieceTime && BuiltScalars == o.BuiltScalars &&
    BuiltRegion == o.BuiltRegion && Resolution == o.Resolution;
}

PsiLevelOfDetail::Key PsiLevelOfDetail::KeyOf(
  vtkDataSet* piece, const Scalars& scalars, const Region& region, int resolution)
{
  Key key;
  key.Piece = piece;
  key.PieceTime = piece ? piece->GetMTime() : 0;
  key.BuiltScalars = scalars;
  key.BuiltRegion = region;
  key.Resolution = resolution;
  return key;
}

bool PsiLevelOfDetail::Drawable(vtkDataSet* piece, const Scalars& scalars)
{
  return piece && piece->GetNumberOfCells() > 0 && !scalars.Array.empty();
}

bool PsiLevelOfDetail::NeedsUpdate(
  vtkDataSet* piece, const Scalars& scalars, const Region& region, int resolution) const
{
  if (!Drawable(piece, scalars))
  {
    return this->Image != nullptr;
  }
  const Key key = KeyOf(piece, scalars, region, resolution);
  return !(this->Image && key == this->Built) && !(!this->Error.empty() && key == this->Failed);
}

bool PsiLevelOfDetail::Update(vtkDataSet* piece, const Scalars& scalars, const Region& region,
  int resolution, const std::function<void(double)>& progress)
{
  if (!Drawable(piece, scalars))
  {
    this->Reset();
    return false;
  }
  if (!this->NeedsUpdate(piece, scalars, region, resolution))
  {
    return false;
  }
  const Key key = KeyOf(piece, scalars, region, resolution);
  this->Reset();
  this->Error.clear();
  try
  {
    const psi::Stopwatch clock;
    const psi::LODImage lod = psi::ResampleForLOD(piece, scalars, region, resolution, progress);
    this->Install(lod, key, clock.Seconds());
  }
  catch (const std::exception& e)
  {
    this->Reset();
    this->Failed = key;
    this->Error = e.what();
    this->ErrorTaken = false;
  }
  return this->Image != nullptr;
}

void PsiLevelOfDetail::SetViewDirection(const double direction[3])
{
  if (this->Image)
  {
    this->Mapper->SetSampleDistance(
      static_cast<float>(psi::LODSampleDistance(this->Image->GetSpacing(), direction)));
  }
}

std::string PsiLevelOfDetail::TakeNewError()
{
  const bool fresh = !this->ErrorTaken;
  this->ErrorTaken = true;
  return fresh ? this->Error : std::string();
}

void PsiLevelOfDetail::Install(const psi::LODImage& lod, const Key& key, double seconds)
{
  this->LastBuildSeconds = seconds;
  if (!lod.Image)
  {
    return; // nothing the full frame draws: no image
  }
  this->Image = lod.Image;
  this->Crop(key.BuiltRegion);
  this->Mapper->SetInputData(this->Image);
  this->Built = key;
}

// In parallel each process draws only its piece's box: the neighbours' images abut there, as
// ordered compositing requires.
void PsiLevelOfDetail::Crop(const Region& region)
{
  this->Mapper->SetCropping(region.Parallel ? 1 : 0);
  if (region.Parallel)
  {
    this->Mapper->SetCroppingRegionPlanes(const_cast<double*>(region.Box));
    this->Mapper->SetCroppingRegionFlagsToSubVolume();
  }
}
