// PsiTetMesh: the tetrahedral mesh as the renderer uses it, gathered from any VTK unstructured
// grid (GL-free). Points are shifted to the centre of the bounds of the points the cells use
// (PsiCellPointBounds.h; float precision far from the origin) and carry their scalar: x, y, z,
// s; each tetrahedron is 4 point ids.
//
// Cells that are not linear tetrahedra and tetrahedra with a non-finite scalar are skipped and
// counted. With cell scalars every tetrahedron gets four private points carrying its constant
// scalar (the scalar is then piecewise constant, as VTK's mappers draw cell data).
#ifndef PsiTetMesh_h
#define PsiTetMesh_h

#include "PsiTetCells.h"
#include "PsiVolumeCoreModule.h"

#include "vtkDataArray.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

class vtkDataArray;
class vtkUnstructuredGridBase;

namespace psi
{

struct PSIVOLUMECORE_EXPORT TetMesh
{
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 }; ///< of the shifted points
  double Shift[3] = { 0, 0, 0 };           ///< subtracted from every input point
  double ScalarRange[2] = { 0, 1 };        ///< of the drawn tetrahedra (never empty)
  /// x, y, z, u per point, where u = UnitScalar(ScalarRange, s) is the point's scalar s as a
  /// fraction of the range, computed in double: 0 and 1 at the range's ends. The GPU never sees
  /// s itself, whose range may be narrower than the smallest normal float (ParaView widens a
  /// field of zeros to [0, 1.18e-38], which a GPU flushes to 0) or far from 0 beside its width.
  std::vector<float> Points4;
  /// The opacity scalar per point as a fraction of OpacityRange, with a separate opacity array
  /// (ScalarComponent::Opacity); empty otherwise.
  std::vector<float> Opacity;
  double OpacityRange[2] = { 0, 1 }; ///< of Opacity over the drawn tetrahedra (never empty)
  /// 4 point ids per tetrahedron; empty when they are the input's own connectivity (Borrowed)
  std::vector<uint32_t> Tets;
  /// The input's connectivity array, when every input cell is a drawable tetrahedron of point
  /// data: the mesh then reads its cells there (Cells) instead of copying them.
  vtkSmartPointer<vtkDataArray> Borrowed;
  /// Input cell of each tetrahedron; empty when tetrahedron i is input cell i for every i.
  std::vector<uint32_t> SourceCells;
  int64_t NonTetCells = 0;   ///< input cells skipped for not being tetrahedra
  int64_t NonFiniteTets = 0; ///< tetrahedra skipped for a NaN or infinite scalar
  double MaxEdgeLength = 0;  ///< bounds every ray segment's length
  double MinEdgeLength = 0;  ///< shortest edge (sets the pre-integration table's length axis)
  bool CellScalars = false;  ///< gathered with cell scalars (private points per tetrahedron)

  size_t NumberOfTets() const
  {
    const size_t ids =
      this->Borrowed ? static_cast<size_t>(this->Borrowed->GetNumberOfValues()) : this->Tets.size();
    return ids / 4;
  }
  /// The four point ids of each tetrahedron, wherever they are kept. A borrowed connectivity
  /// holds vtkCellArray's 64- or 32-bit ids; 32-bit ids are below 2^31 and read as unsigned.
  TetCells Cells() const
  {
    if (!this->Borrowed)
    {
      return TetCells(this->Tets.data());
    }
    const void* ids = this->Borrowed->GetVoidPointer(0);
    return this->Borrowed->GetDataTypeSize() == 8 ? TetCells(static_cast<const vtkTypeInt64*>(ids))
                                                  : TetCells(static_cast<const uint32_t*>(ids));
  }
  size_t NumberOfPoints() const { return this->Points4.size() / 4; }
};

/// Where s lies in `range`, as a fraction of its width: 0 at range[0], 1 at range[1]. Every
/// scalar the GPU compares or looks up (points, isovalues, transfer-function nodes) is one.
inline double UnitScalar(const double range[2], double s)
{
  return (s - range[0]) / (range[1] - range[0]);
}

/// Whether the renderer can draw scalar s: finite and within float range. Tetrahedra touching
/// another value are skipped; isovalues outside it are dropped.
inline bool FiniteScalar(double s)
{
  return std::isfinite(s) && std::abs(s) < 1e37;
}

/// Which value of a tuple is the scalar: a component (clamped to the array's), or the magnitude
/// of the whole tuple (Magnitude), as a color map's vector mode says (vtkScalarsToColors).
struct ScalarComponent
{
  static constexpr int Magnitude = -1;
  static constexpr int NoOpacity = -2;
  int Index = 0;
  /// The component that holds a separate opacity scalar (ParaView's combined color + opacity
  /// array, UseSeparateOpacityArray: component 1), or NoOpacity.
  int Opacity = NoOpacity;
};

/// The scalar of tuple i of `array` (component or magnitude, see ScalarComponent; the color
/// scalar, not the separate opacity).
PSIVOLUMECORE_EXPORT double ScalarValue(vtkDataArray* array, int64_t i, ScalarComponent c);

/// Sets the mesh's MaxEdgeLength and MinEdgeLength (the shortest non-zero edge) from its
/// tetrahedra's edges.
PSIVOLUMECORE_EXPORT void MeasureEdgeLengths(TetMesh& mesh);

/// Gathers the tetrahedra of `input` with the scalars of `scalars` (point or cell data).
PSIVOLUMECORE_EXPORT TetMesh GatherTetMesh(vtkUnstructuredGridBase* input, vtkDataArray* scalars,
  bool cellScalars, ScalarComponent component = ScalarComponent());

/// A new time step on the same mesh: replaces the point scalars (and separate opacity scalars) of
/// a mesh gathered with point data by those of `scalars` (one tuple per input point) and
/// recomputes the scalar ranges,
/// without gathering points and cells again. Returns false, leaving the mesh unchanged, when
/// that would change which tetrahedra are drawn (a non-finite scalar now or before, or a
/// mesh gathered with cell scalars): gather the mesh again then.
PSIVOLUMECORE_EXPORT bool UpdateTetMeshScalars(
  TetMesh& mesh, vtkDataArray* scalars, ScalarComponent component = ScalarComponent());

/// Face neighbours of the gathered tetrahedra (4 per tetrahedron, face i opposite vertex i, -1 on
/// the boundary) taken from a per-cell 4-component array of input cell ids, such as the
/// `FaceNeighbors` array of vtkPsiConformingTetrahedralize; neighbours that were skipped become
/// -1. Returns false (and leaves `neighbors` empty) when the array does not fit the mesh.
PSIVOLUMECORE_EXPORT bool FaceNeighborsFromArray(const TetMesh& mesh, vtkDataArray* cellNeighbors,
  int64_t numInputCells, std::vector<int32_t>& neighbors);

/// What was skipped and why, as a sentence for a warning ("" when nothing was skipped).
PSIVOLUMECORE_EXPORT std::string DescribeSkippedCells(const TetMesh& mesh);

/// Smoothed point gradients of the piecewise-linear scalar (isosurface normals): each
/// tetrahedron's gradient weighted by its volume, averaged over the tetrahedra sharing the point.
/// x, y, z, 0 per point, in the mesh's (shifted) coordinates.
PSIVOLUMECORE_EXPORT std::vector<float> PointGradients(const TetMesh& mesh);

} // namespace psi

#endif
