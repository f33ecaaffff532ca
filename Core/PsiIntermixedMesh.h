// PsiIntermixedMesh: several volumes of a scene drawn as one (GL-free). Projected tetrahedra put
// the cells of every volume into one visibility order and composite them in one pass, which ray
// casters of separate images cannot (VTK's vtkMultiVolume serves image data only): the
// tetrahedra of all volumes go into one mesh in world coordinates, each volume keeping its own
// transfer function and unit distance in a slot of its own of one concatenated table.
//
// The slots. Volume k of n is sampled at S scalars over its own range, as alone (tau =
// opacity / its unit distance, psi::SampleTransferFunction); the table holds the n samplings one
// after the other. Its unit scalar u (a fraction of its own range, psi::TetMesh::Points4) becomes
//     U = (k S + u (S - 1)) / (n S - 1),
// sample position k S + u (S - 1) as a fraction of the whole table: the shaders' lookup
// (texcoord = U (nS - 1) / nS + 0.5 / nS, on texel centres) then reads sample k S + u (S - 1),
// exactly where volume k alone would read its own table. U is affine in u, so the scalar stays
// linear along a ray segment in one tetrahedron, and between two samples of one slot: a
// segment's interpolation never reaches another volume's samples.
#ifndef PsiIntermixedMesh_h
#define PsiIntermixedMesh_h

#include "PsiTetMesh.h"
#include "PsiTransferFunctionNodes.h"
#include "PsiTransferFunctionTable.h"
#include "PsiVolumeCoreModule.h"

#include <array>
#include <cstdint>
#include <vector>

namespace psi
{

/// One volume of an intermixed scene: its gathered mesh and the matrix that places its
/// (unshifted) points in the world, row-major (vtkVolume::GetMatrix; identity by default).
struct IntermixedVolume
{
  const TetMesh* Mesh = nullptr;
  std::array<double, 16> ModelToWorld{ { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 } };
};

/// U of the header: where the unit scalar `u` of slot `slot` of `slots`, sampled at `samples`
/// scalars each, lies as a fraction of the concatenated table.
inline double SlotScalar(int slot, int slots, int samples, double u)
{
  return (slot * double(samples) + u * (samples - 1.0)) / (slots * double(samples) - 1.0);
}

/// The volumes' tetrahedra as one mesh: points in world coordinates shifted to the centre of
/// the bounds of the points the cells use, scalars (and separate opacity scalars, where any
/// volume has them: a volume without reads its color scalar's fraction, over whose range its
/// attenuation is then sampled) as slot scalars of `samples` samples per volume, cells one
/// volume after the other. The scalar ranges are [0, 1]; edge lengths are measured in the world.
PSIVOLUMECORE_EXPORT TetMesh IntermixMeshes(
  const std::vector<IntermixedVolume>& volumes, int samples);

/// The tables of the volumes, each sampled at the same number of scalars, one after the other:
/// the table of the intermixed mesh (domain [0, 1] in slot scalars).
PSIVOLUMECORE_EXPORT TransferFunctionTable IntermixTables(
  const std::vector<TransferFunctionTable>& tables);

/// Each volume's adaptive-sampling nodes (psi::SampleTransferFunctionNodes over `ranges[k]`,
/// its own scalar range) as nodes of the slot scalars (SlotScalar with `samples`), one volume
/// after the other: a segment never leaves its volume's slot, so it splits at that volume's
/// nodes only, at the same fractions of its range as alone. MaxDeviation: the largest of theirs.
PSIVOLUMECORE_EXPORT TransferFunctionNodes IntermixNodes(
  const std::vector<TransferFunctionNodes>& nodes, const std::vector<std::array<double, 2>>& ranges,
  int samples);

/// Prefix counts of non-zero opacity (psi::OpacityPrefixCounts) of each volume's table, one
/// after the other, each continuing the count of those before it.
PSIVOLUMECORE_EXPORT std::vector<float> IntermixOpacityPrefixes(
  const std::vector<std::vector<float>>& prefixes);

/// Face neighbours of the intermixed mesh (4 per tetrahedron, face i opposite vertex i, -1 on the
/// boundary; psi::ComputeTetNeighbors) with the points welded by position: tetrahedra of two
/// volumes that share a face (an interface between regions, each volume with its own points there)
/// are neighbours, so that MPVONC orders them exactly across it, as within one mesh, instead of
/// by their keys (Williams 1992 §6: between components only the heuristic order).
PSIVOLUMECORE_EXPORT std::vector<int32_t> WeldedFaceNeighbors(const TetMesh& mesh);

} // namespace psi

#endif
