#include "PsiLODImage.h"

#include "PsiLatticeSampling.h"
#include "PsiTransferFunctionAnalysis.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

namespace
{
// The mask of the lattice points inside the drawn tetrahedra (removed once they are hidden).
constexpr const char* MaskName = "PsiLODInside";

// The lattice: `resolution` samples (at least 2) along each side of `bounds`, spanning them. In
// parallel every process computes it from the same global bounds, so that the processes' samples
// are points of one lattice.
psi::Lattice GlobalLattice(const double bounds[6], int resolution)
{
  psi::Lattice l;
  const double sides[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
  for (int k = 0; k < 3; ++k)
  {
    // `resolution` samples along every side, as ParaView's 'Resample To Image' samples: along
    // the longest side only (the others in proportion), the Blunt Fin's level of detail was 1.84
    // from the exact image against 0.83 for 64^3 (/255, docs/decisions.md "Interaction")
    l.Dims[k] = std::max(2, resolution);
    // From face to face of the bounds: psi::SampleOnLattice keeps a point on a boundary face
    // within its tolerance (vtkProbeFilter, used before it, lost the last layer there unless the
    // lattice lay inside the bounds: 1.5/255 against 0.7 on the Blunt Fin).
    l.Spacing[k] = sides[k] > 0 ? sides[k] / (l.Dims[k] - 1) : 1;
    l.Origin[k] = bounds[2 * k];
  }
  return l;
}

vtkSmartPointer<vtkImageData> LatticeImage(const psi::Lattice& l)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetOrigin(l.Origin);
  image->SetSpacing(l.Spacing);
  image->SetDimensions(l.Dims);
  return image;
}

// In parallel, the lattice points beyond this process's box that its piece does not cover (the
// neighbour holds their cells) take the value of the nearest point inside the box, instead of
// hiding the last lattice cell before the box's face (a seam); the cropping draws nothing beyond
// the box, so these values only shape the interpolation between the last point and the face.
void FillBeyondBox(vtkImageData* image, const char* maskName, const double box[6])
{
  vtkPointData* pd = image->GetPointData();
  vtkDataArray* mask = pd->GetArray(maskName);
  const int* ext = image->GetExtent();
  const double* o = image->GetOrigin();
  const double* h = image->GetSpacing();
  int in[6]; // the extent of the points inside the box
  for (int k = 0; k < 3; ++k)
  {
    in[2 * k] = std::max(ext[2 * k], static_cast<int>(std::ceil((box[2 * k] - o[k]) / h[k])));
    in[2 * k + 1] =
      std::min(ext[2 * k + 1], static_cast<int>(std::floor((box[2 * k + 1] - o[k]) / h[k])));
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
  // The ghost array only where a point is hidden: with one, the ray caster tests 7 lattice points
  // of it per sample, which a mesh filling its box (every point valid) need not pay.
  vtkUnsignedCharArray* points = nullptr;
  for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
  {
    if (mask->GetTuple1(i) == 0)
    {
      points = points ? points : image->AllocatePointGhostArray();
      points->SetValue(i, points->GetValue(i) | vtkDataSetAttributes::HIDDENPOINT);
    }
  }
  image->GetPointData()->RemoveArray(maskName);
}

// The image of the samples: the scalar (and separate opacity) back in the array's own values,
// and a mask of the lattice points inside the drawn tetrahedra.
vtkSmartPointer<vtkImageData> SampledImage(
  const psi::TetMesh& mesh, const psi::Lattice& lattice, const psi::LatticeSamples& samples)
{
  vtkSmartPointer<vtkImageData> image = LatticeImage(lattice);
  const vtkIdType n = image->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> values;
  values->SetName(psi::LODArrayName);
  values->SetNumberOfComponents(samples.Opacity.empty() ? 1 : 2);
  values->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName(MaskName);
  mask->SetNumberOfTuples(n);
  const double* r = mesh.ScalarRange;
  const double* o = mesh.OpacityRange;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool inside = samples.Tet[i] >= 0;
    mask->SetValue(i, inside ? 1 : 0);
    // TetMesh's u back to the scalar: s = r0 + u (r1 - r0) (psi::UnitScalar inverted). A hidden
    // point takes the range's low end, not 0: the ray caster spans its transfer-function table
    // over the image's scalar range, and a 0 there widened it (a constant field of 7 drew a
    // table over [0, 7] for a color map over [7, 7.001]: speckles).
    values->SetTypedComponent(i, 0, r[0] + (inside ? samples.Scalar[i] : 0) * (r[1] - r[0]));
    if (!samples.Opacity.empty())
    {
      values->SetTypedComponent(i, 1, o[0] + (inside ? samples.Opacity[i] : 0) * (o[1] - o[0]));
    }
  }
  image->GetPointData()->AddArray(values);
  image->GetPointData()->AddArray(mask);
  return image;
}
} // namespace

namespace psi
{

LODScalars LODScalarsOf(
  vtkUnstructuredGridVolumeMapper* mapper, vtkVolumeProperty* property, vtkDataSet* piece)
{
  LODScalars s;
  int cellFlag = -1;
  vtkDataArray* a = piece
    ? vtkAbstractMapper::GetScalars(piece, mapper->GetScalarMode(), mapper->GetArrayAccessMode(),
        mapper->GetArrayId(), mapper->GetArrayName(), cellFlag)
    : nullptr;
  if (a && a->GetName() && (cellFlag == 0 || cellFlag == 1))
  {
    s.Array = a->GetName();
    s.Cells = cellFlag == 1;
    s.Component = psi::ColorMapComponent(property, a->GetNumberOfComponents());
  }
  return s;
}

bool LODRegion::operator==(const LODRegion& o) const
{
  return Parallel == o.Parallel && std::equal(Global, Global + 6, o.Global) &&
    std::equal(Box, Box + 6, o.Box);
}

void LODOpacityFunction(vtkPiecewiseFunction* opacity, vtkPiecewiseFunction* out, int subdivisions)
{
  out->RemoveAllPoints();
  out->SetClamping(opacity->GetClamping());
  const int n = opacity->GetSize();
  double node[4], next[4];
  for (int i = 0; i < n; ++i)
  {
    opacity->GetNodeValue(i, node);
    const int pieces = i + 1 < n ? std::max(1, subdivisions) : 1;
    if (i + 1 < n)
    {
      opacity->GetNodeValue(i + 1, next);
    }
    for (int k = 0; k < pieces; ++k)
    {
      const double x = k == 0 ? node[0] : node[0] + (next[0] - node[0]) * k / pieces;
      const double a = k == 0 ? node[1] : opacity->GetValue(x);
      out->AddPoint(x, 1 - std::exp(-std::max(a, 0.0))); // a' = 1 - exp(-a)
    }
  }
}

void LODVolumeProperty(vtkVolumeProperty* property, vtkVolumeProperty* out)
{
  out->DeepCopy(property);
  // the level of detail's image has one scalar (and a dependent opacity): the first function
  vtkNew<vtkPiecewiseFunction> remapped;
  LODOpacityFunction(property->GetScalarOpacity(0), remapped);
  out->SetScalarOpacity(0, remapped);
}

double LODSampleDistance(const double spacing[3], const double direction[3])
{
  const double length = std::sqrt(
    direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  double cells = 0; // lattice cells per unit of length along the ray, squared
  for (int k = 0; k < 3; ++k)
  {
    const double d = length > 0 ? direction[k] / length : 1 / std::sqrt(3.0);
    cells += (d / spacing[k]) * (d / spacing[k]);
  }
  return 1 / std::sqrt(cells);
}

LODImage ResampleForLOD(vtkDataSet* piece, const LODScalars& scalars, const LODRegion& region,
  int resolution, const std::function<void(double)>& progress)
{
  auto* grid = vtkUnstructuredGridBase::SafeDownCast(piece);
  vtkDataSetAttributes* data = !grid ? nullptr
    : scalars.Cells                  ? static_cast<vtkDataSetAttributes*>(grid->GetCellData())
                                     : grid->GetPointData();
  vtkDataArray* array =
    data && !scalars.Array.empty() ? data->GetArray(scalars.Array.c_str()) : nullptr;
  LODImage lod;
  if (!array || grid->GetNumberOfCells() == 0)
  {
    return lod;
  }
  const TetMesh mesh = GatherTetMesh(grid, array, scalars.Cells, scalars.Component);
  if (mesh.NumberOfTets() == 0)
  {
    return lod;
  }
  // serially the mesh's bounds, unshifted: those of the points the cells use (an unused point
  // may lie anywhere)
  double used[6];
  for (int k = 0; k < 6; ++k)
  {
    used[k] = mesh.Bounds[k] + mesh.Shift[k / 2];
  }
  const Lattice lattice = GlobalLattice(region.Parallel ? region.Global : used, resolution);
  lod.Image = SampledImage(mesh, lattice, SampleOnLattice(mesh, lattice, progress));
  if (region.Parallel)
  {
    FillBeyondBox(lod.Image, MaskName, region.Box);
  }
  BlankOutside(lod.Image, MaskName);
  return lod;
}

} // namespace psi
