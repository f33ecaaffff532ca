// PsiVisibilitySort: one interface over the visibility sorts of a tetrahedral mesh (GL-free), as
// VTK's vtkVisibilitySort is for its projected-tetrahedra mapper. Each sort owns what it derives
// from the mesh: the centroid sort its centroids (Maximo et al. 2010 §3.1), MPVONC its face
// neighbours (Williams 1992), taken from the input when it carries them and computed otherwise.
#ifndef PsiVisibilitySort_h
#define PsiVisibilitySort_h

#include "PsiSortDirection.h"
#include "PsiTetMesh.h"
#include "PsiVolumeCoreModule.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace psi
{
class PSIVOLUMECORE_EXPORT VisibilitySort
{
public:
  virtual ~VisibilitySort();
  /// The mesh to order from now on (kept by pointer: it must outlive the sort's use of it).
  /// `faceNeighbors`, when not empty, are the mesh's face neighbours (see
  /// psi::FaceNeighborsFromArray); a sort that needs them checks them against the mesh and
  /// computes its own when they do not match.
  virtual void SetMesh(const TetMesh* mesh, std::vector<int32_t> faceNeighbors) = 0;
  /// All tetrahedra, farthest first. eye: camera position, or with parallel = true the view
  /// direction (from the eye into the scene), in the mesh's coordinates. Returns the number of
  /// cycles the sort had to break (0 for sorts that never meet any). `emitted`, when set, is
  /// called with the number of leading entries of `order` that are final, as they become final
  /// (MPVONC: every psi::EmittedStep; the centroid sort: once, at the end) and with all of them
  /// at the end; `order` has its final size before the first call. NearestFirst: all
  /// tetrahedra in a visibility order for front-to-back compositing instead.
  virtual size_t Sort(const double eye[3], bool parallel, std::vector<uint32_t>& order,
    const std::function<void(size_t)>& emitted = {},
    SortDirection direction = SortDirection::FarthestFirst) = 0;
};

PSIVOLUMECORE_EXPORT std::unique_ptr<VisibilitySort> NewCentroidSort();
PSIVOLUMECORE_EXPORT std::unique_ptr<VisibilitySort> NewMPVONCSort();

/// Whether every neighbour entry names a tetrahedron that has the face's three points (by
/// position, so that meshes with private points per cell check too), and no entry is out of range.
PSIVOLUMECORE_EXPORT bool FaceNeighborsMatch(
  const TetMesh& mesh, const std::vector<int32_t>& faceNeighbors);
} // namespace psi

#endif
