#include "PsiVolumeLOD.h"

#include "PsiParallel.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkProbeFilter.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>

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
  }
  void Render(vtkRenderer* ren, vtkVolume* vol) override
  {
    const auto t0 = std::chrono::steady_clock::now();
    this->Superclass::Render(ren, vol);
    this->LastSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  double LastSeconds = 0;
};
vtkStandardNewMacro(PsiTimedVolumeMapper);

// A copy of `piece`'s structure with only the arrays the level of detail draws, so that the
// image holds those alone (the probe resamples every array it is given).
vtkSmartPointer<vtkDataSet> WithArrays(vtkDataSet* piece, const PsiVolumeLOD::Arrays& arrays)
{
  vtkSmartPointer<vtkDataSet> copy;
  copy.TakeReference(piece->NewInstance());
  copy->CopyStructure(piece);
  for (const std::string& name : { arrays.Color, arrays.Opacity })
  {
    if (vtkDataArray* a = piece->GetPointData()->GetArray(name.c_str()))
    {
      copy->GetPointData()->AddArray(a);
    }
    else if (vtkDataArray* c = piece->GetCellData()->GetArray(name.c_str()))
    {
      copy->GetCellData()->AddArray(c);
    }
  }
  return copy;
}

// Samples whose value is not finite are hidden (as 'Psi Volume' skips their cells) and given a
// finite value, so that no NaN reaches the ray caster's scalar range.
void BlankNonFinite(vtkImageData* image, const PsiVolumeLOD::Arrays& arrays)
{
  vtkPointData* pd = image->GetPointData();
  vtkUnsignedCharArray* ghosts = image->GetPointGhostArray();
  for (const std::string& name : { arrays.Color, arrays.Opacity })
  {
    vtkDataArray* a = name.empty() ? nullptr : pd->GetArray(name.c_str());
    for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
      {
        if (!std::isfinite(a->GetComponent(i, c)))
        {
          ghosts = ghosts ? ghosts : image->AllocatePointGhostArray();
          ghosts->SetValue(i, ghosts->GetValue(i) | vtkDataSetAttributes::HIDDENPOINT);
          a->SetComponent(i, c, 0);
        }
      }
    }
  }
}

// The lattice: `resolution` samples (at least 2) along each side of `bounds`, spanning them. In
// parallel every process computes it from the same global bounds, so that the processes' samples
// are points of one lattice.
struct Lattice
{
  int Dims[3];
  double Spacing[3];
  double Origin[3];
};

Lattice GlobalLattice(const double bounds[6], int resolution)
{
  Lattice l;
  const double sides[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
  for (int k = 0; k < 3; ++k)
  {
    // `resolution` samples along every side, as ParaView's 'Resample To Image' samples: along
    // the longest side only (the others in proportion), the Blunt Fin's level of detail was 1.84
    // from the exact image against 0.83 for 64^3 (/255, docs/decisions.md "Interaction")
    l.Dims[k] = std::max(2, resolution);
    // The lattice lies a millionth of each side inside the bounds: vtkProbeFilter finds the
    // lattice points in a cell by floor((max - origin) / spacing), which for the points on the
    // bounds' upper faces can round one point short, and the mesh's whole last layer of lattice
    // points was then outside (a missing slab, 1.5/255 against 0.7 on the Blunt Fin).
    const double inset = 1e-6 * sides[k];
    l.Spacing[k] = sides[k] > 0 ? (sides[k] - 2 * inset) / (l.Dims[k] - 1) : 1;
    l.Origin[k] = bounds[2 * k] + inset;
  }
  return l;
}

vtkSmartPointer<vtkImageData> LatticeImage(const Lattice& l)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetOrigin(l.Origin);
  image->SetSpacing(l.Spacing);
  image->SetDimensions(l.Dims);
  return image;
}

// In parallel, the lattice points beyond this process's cut that its piece does not cover (the
// neighbour holds their cells) take the value of the nearest point inside the cut, instead of
// hiding the last lattice cell before the cut (a seam); the cropping draws nothing beyond the
// cut, so these values only shape the interpolation between the last point and the cut.
void FillBeyondCut(vtkImageData* image, const char* maskName, const double cut[6])
{
  vtkPointData* pd = image->GetPointData();
  vtkDataArray* mask = pd->GetArray(maskName);
  const int* ext = image->GetExtent();
  const double* o = image->GetOrigin();
  const double* h = image->GetSpacing();
  int in[6]; // the extent of the points inside the cut
  for (int k = 0; k < 3; ++k)
  {
    in[2 * k] = std::max(ext[2 * k], static_cast<int>(std::ceil((cut[2 * k] - o[k]) / h[k])));
    in[2 * k + 1] =
      std::min(ext[2 * k + 1], static_cast<int>(std::floor((cut[2 * k + 1] - o[k]) / h[k])));
    if (!mask || in[2 * k] > in[2 * k + 1])
    {
      return;
    }
  }
  for (int z = ext[4]; z <= ext[5]; ++z)
  {
    for (int y = ext[2]; y <= ext[3]; ++y)
    {
      for (int x = ext[0]; x <= ext[1]; ++x)
      {
        int p[3] = { x, y, z };
        int q[3] = { std::clamp(x, in[0], in[1]), std::clamp(y, in[2], in[3]),
          std::clamp(z, in[4], in[5]) };
        const vtkIdType pid = image->ComputePointId(p), qid = image->ComputePointId(q);
        if (pid == qid || mask->GetTuple1(pid) != 0 || mask->GetTuple1(qid) == 0)
        {
          continue;
        }
        for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
        {
          if (vtkDataArray* array = pd->GetArray(a))
          {
            array->SetTuple(pid, qid, array);
          }
        }
      }
    }
  }
}

// Samples outside the mesh are hidden (the ray caster skips a sample whose nearest lattice point,
// or the one half a spacing away along an axis, is hidden: transparent outside the mesh). Unlike
// VTK's vtkResampleToImage, the lattice cells that touch a hidden point are not hidden as well:
// that hides a whole layer of cells inside the mesh along its boundary (on the Blunt Fin 0.84/255
// from the exact image with them, 0.72 without, docs/decisions.md "Interaction").
void BlankOutside(vtkImageData* image, const char* maskName)
{
  vtkDataArray* mask = image->GetPointData()->GetArray(maskName);
  if (!mask)
  {
    return;
  }
  vtkUnsignedCharArray* points = image->AllocatePointGhostArray();
  for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
  {
    if (mask->GetTuple1(i) == 0)
    {
      points->SetValue(i, points->GetValue(i) | vtkDataSetAttributes::HIDDENPOINT);
    }
  }
  image->GetPointData()->RemoveArray(maskName);
}
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

PsiVolumeLOD::~PsiVolumeLOD() = default;

void PsiVolumeLOD::Reset()
{
  this->Image = nullptr;
  this->Piece = nullptr;
  this->PieceTime = 0;
  this->BuiltResolution = 0;
  this->Mapper->RemoveAllInputs();
}

bool PsiVolumeLOD::Region::operator==(const Region& o) const
{
  return Parallel == o.Parallel && std::equal(Global, Global + 6, o.Global) &&
    std::equal(Cut, Cut + 6, o.Cut);
}

bool PsiVolumeLOD::IsCurrent(
  vtkDataSet* piece, const Arrays& arrays, const Region& region, int resolution) const
{
  return this->Image && piece == this->Piece && piece->GetMTime() == this->PieceTime &&
    arrays == this->BuiltArrays && region == this->BuiltRegion &&
    resolution == this->BuiltResolution;
}

bool PsiVolumeLOD::Update(
  vtkDataSet* piece, const Arrays& arrays, const Region& region, int resolution)
{
  if (!piece || piece->GetNumberOfCells() == 0 || arrays.Color.empty())
  {
    this->Reset();
    return false;
  }
  if (this->IsCurrent(piece, arrays, region, resolution))
  {
    return false;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const double* bounds = piece->GetBounds();
  const Lattice lattice = GlobalLattice(region.Parallel ? region.Global : bounds, resolution);
  vtkNew<vtkProbeFilter> probe;
  probe->SetInputData(LatticeImage(lattice));
  probe->SetSourceData(WithArrays(piece, arrays));
  psi::Parallel([&] { probe->Update(); });
  this->Image = vtkSmartPointer<vtkImageData>::New();
  this->Image->ShallowCopy(probe->GetOutput());
  if (region.Parallel)
  {
    FillBeyondCut(this->Image, probe->GetValidPointMaskArrayName(), region.Cut);
  }
  BlankOutside(this->Image, probe->GetValidPointMaskArrayName());
  BlankNonFinite(this->Image, arrays);
  this->Crop(region);
  // One sample per mean lattice spacing: on the Blunt Fin 0.67/255 from the exact image, against
  // 0.70 at half of it for twice the samples (docs/decisions.md "Interaction").
  this->Mapper->SetSampleDistance(
    static_cast<float>((lattice.Spacing[0] + lattice.Spacing[1] + lattice.Spacing[2]) / 3));
  this->Mapper->SetInputData(this->Image);
  this->Mapper->SelectScalarArray(arrays.Color.c_str());
  this->Piece = piece;
  this->PieceTime = piece->GetMTime();
  this->BuiltArrays = arrays;
  this->BuiltRegion = region;
  this->BuiltResolution = resolution;
  this->LastBuildSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return true;
}

// In parallel each process draws only its cut: the neighbours' images abut there, as ordered
// compositing requires, and no lattice cell is drawn twice.
void PsiVolumeLOD::Crop(const Region& region)
{
  this->Mapper->SetCropping(region.Parallel ? 1 : 0);
  if (region.Parallel)
  {
    this->Mapper->SetCroppingRegionPlanes(const_cast<double*>(region.Cut));
    this->Mapper->SetCroppingRegionFlagsToSubVolume();
  }
}
