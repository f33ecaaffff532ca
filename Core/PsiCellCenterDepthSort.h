// PsiCellCenterDepthSort: the centroid order of tetrahedra for projected-tetrahedra compositing, as
// VTK's vtkCellCenterDepthSort orders cells, back to front or front to back (PsiSortDirection.h).
//
// Centroid sort (Maximo, Marroquim & Farias 2010, HAPT §3.1): each tetrahedron is keyed by the
// distance from the eye to its centroid (perspective) or by the centroid's depth along the view
// direction (parallel), and the keys are sorted in parallel (vtkSMPTools::Sort). Approximate:
// adjacent cells of very different size can be misordered; MPVONC (exact for convex meshes) is
// its own sort method.
#ifndef PsiCellCenterDepthSort_h
#define PsiCellCenterDepthSort_h

#include "PsiTetCells.h"
#include "PsiVolumeCoreModule.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace psi
{

/// Centroids (x, y, z per tetrahedron) of `numTets` cells given by 4 point ids each.
PSIVOLUMECORE_EXPORT std::vector<float> ComputeCentroids(
  const float* points4, TetCells tets, size_t numTets);

/// Fills `order` with the ids of all tetrahedra, farthest first.
/// eye: camera position (perspective) or, with parallel = true, the view direction (from the eye
/// into the scene), all in the same coordinates as the centroids.
PSIVOLUMECORE_EXPORT void SortBackToFront(const std::vector<float>& centroids, const double eye[3],
  bool parallel, std::vector<uint32_t>& order);

} // namespace psi

#endif
