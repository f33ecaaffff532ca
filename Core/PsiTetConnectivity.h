// PsiTetConnectivity: face neighbours of a tetrahedral mesh (GL-free).
//
// The adjacency ("the face shared with which tetrahedron") is the first auxiliary structure of
// MPVONC (Maximo, Marroquim & Farias 2010, HAPT §3.1: "the adjacency list and the precomputed
// face normals"; Williams 1992, §3, the mesh's adjacency graph). Face i of a tetrahedron is the
// face opposite its vertex i; its neighbour is -1 on the mesh boundary.
//
// Method: a counting sort of the 4 n faces by their smallest point id (one bucket per point),
// then, per bucket, a sort by the two other (sorted) ids; equal keys are the same face. Linear
// in the number of faces plus the small per-bucket sorts; buckets run in parallel (vtkSMPTools).
#ifndef PsiTetConnectivity_h
#define PsiTetConnectivity_h

#include "PsiVolumeCoreModule.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include "PsiTetCells.h"

namespace psi
{

struct TetConnectivityResult
{
  size_t InteriorFaces = 0;    ///< faces shared by exactly two tetrahedra (counted once)
  size_t BoundaryFaces = 0;    ///< faces of exactly one tetrahedron
  size_t NonManifoldFaces = 0; ///< distinct faces shared by more than two tetrahedra
  size_t NumberOfPoints = 0;   ///< 1 + the largest point id seen
};

/// Fills `neighbors` (4 per tetrahedron) with the tetrahedron across face i (opposite vertex i),
/// or -1 for a boundary face. Faces shared by more than two tetrahedra (non-manifold) are counted
/// and get -1 on every side: no pairing of them is right for a visibility order.
/// numPoints may be 0 (then it is computed as 1 + the largest id). numTets must be < 2^31.
/// The faces are paired in passes of at most `facesPerPass` faces (0: an eighth of them, at
/// least 2^20), so that the working memory stays a fraction of the mesh's.
PSIVOLUMECORE_EXPORT TetConnectivityResult ComputeTetNeighbors(TetCells tets, size_t numTets,
  size_t numPoints, std::vector<int32_t>& neighbors, size_t facesPerPass = 0);

/// Bit i set (1 << i) where face i of the tetrahedron is a boundary face (neighbour -1).
PSIVOLUMECORE_EXPORT std::vector<uint8_t> BoundaryFaceFlags(const std::vector<int32_t>& neighbors);

} // namespace psi

#endif
