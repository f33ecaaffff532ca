// PsiMPVONCSort: visibility ordering of a tetrahedral mesh after Williams' MPVO/MPVONC
// (P. L. Williams, "Visibility-Ordering Meshed Polyhedra", ACM TOG 11(2), 1992), the exact CPU
// sort HAPT compares with its centroid sorts (Maximo, Marroquim & Farias 2010, HAPT §3.1).
//
// What is exact and what is not:
//  * Exact (up to floating-point sign decisions on nearly edge-on faces): for every interior
//    face whose plane does not contain the eye, the tetrahedron behind the face is emitted before
//    the one in front, whenever the "behind" relation across faces is acyclic (Williams §3-4:
//    then any topological order of that DAG is a visibility order of a convex, connected mesh).
//  * Approximate (Williams' MPVONC heuristics, §6): for non-convex or disconnected meshes the
//    face DAG misses the occlusions through empty space (cavities, gaps between components).
//    The cells that start the sort are those whose only faces pointing away from the viewer are
//    boundary faces; among all tetrahedra ready to be emitted we always take the farthest one
//    (distance from the eye to the centroid, or depth along the view direction: the key of
//    psi::SortBackToFront). Between disconnected components and across concavities the order is
//    therefore the centroid order; inside a component it is the exact DAG order.
//  * Cycles (Williams §7; they occur in non-Delaunay meshes and with inconsistent neighbour
//    data): when no tetrahedron is ready but some remain, the farthest remaining one is emitted
//    anyway and counted in CyclesBroken. Faces whose plane passes through the eye (or, in
//    parallel projection, contains the view direction) impose no order (either order is
//    correct for an edge-on face) and are counted in DegenerateFaces.
// The result is always a permutation of all tetrahedra, farthest first, like SortBackToFront.
#ifndef PsiMPVONCSort_h
#define PsiMPVONCSort_h

#include "PsiSortDirection.h"
#include "PsiTetCells.h"
#include "PsiVolumeCoreModule.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace psi
{

struct MPVONCResult
{
  size_t CyclesBroken = 0;        ///< tetrahedra emitted while none was ready (cycle breaks)
  size_t ViolatedConstraints = 0; ///< face constraints the cycle breaks had to violate
  size_t Constraints = 0;         ///< interior faces that impose an order
  size_t DegenerateFaces = 0;     ///< interior faces seen edge-on (or of flat tetrahedra)
  size_t InconsistentFaces = 0;   ///< neighbour entries without a reciprocal entry (ignored)
  size_t Sources = 0;             ///< tetrahedra with nothing behind them across a face
};

/// Orders all `numTets` tetrahedra back to front (farthest first) into `order`.
/// points4: x, y, z, scalar per point (the renderer's layout); tets: 4 point ids each;
/// neighbors: 4 per tetrahedron, face i opposite vertex i, -1 on the boundary
/// (psi::ComputeTetNeighbors). eye: the camera position, or with parallel = true the view
/// direction (from the eye into the scene), as for psi::SortBackToFront.
/// The relation across a face is decided once, from the face of the tetrahedron with the smaller
/// id (a neighbour entry without a reciprocal one is ignored), so both sides always agree.
/// The order is emitted farthest first, so its beginning is final long before the sort ends:
/// `emitted`, when set, is called with the number of entries of `order` that are final (every
/// EmittedStep tetrahedra, and once with numTets at the end). `order` has its final size before
/// the first call, so another thread may read the entries reported so far.
/// SortDirection::NearestFirst emits the same DAG's order reversed in the same way (a tetrahedron
/// after every neighbour in front of it, the nearest ready one first), for front-to-back
/// compositing; it is as exact, and streams as early.
PSIVOLUMECORE_EXPORT MPVONCResult SortMPVONC(const float* points4, TetCells tets, size_t numTets,
  const int32_t* neighbors, const double eye[3], bool parallel, std::vector<uint32_t>& order,
  const std::function<void(size_t)>& emitted = {},
  SortDirection direction = SortDirection::FarthestFirst);

/// How often SortMPVONC reports its progress, in tetrahedra.
constexpr size_t EmittedStep = 4096;

} // namespace psi

#endif
