// PsiLatticeSampling: the scalar of a tetrahedral mesh (psi::TetMesh, exactly what the full frame
// draws) sampled at the points of a regular lattice, GL-free. Each tetrahedron visits the lattice
// points inside its bounding box and keeps those inside itself (barycentric coordinates, the
// linear interpolation of Röttger, Kraus and Ertl 2000 §2 within one cell), so the cost goes with
// the tetrahedra plus the lattice points they cover, with no point locator: a mesh finer than its
// lattice, the common case, costs one bounding box per tetrahedron.
//
// A lattice point on a face shared by two tetrahedra, or on a face within the tolerance, belongs
// to the lowest-numbered tetrahedron that contains it, so that the result does not depend on the
// threads' order (an atomic minimum per point, then the interpolation from that owner).
#ifndef PsiLatticeSampling_h
#define PsiLatticeSampling_h

#include "PsiTetMesh.h"
#include "PsiVolumeCoreModule.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace psi
{

/// A regular lattice: Dims points along each axis from Origin, Spacing apart (world coordinates,
/// not the mesh's shifted ones).
struct Lattice
{
  int Dims[3] = { 0, 0, 0 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  int64_t NumberOfPoints() const { return int64_t(Dims[0]) * Dims[1] * Dims[2]; }
  /// Point index of (i, j, k), x fastest (vtkImageData's order).
  int64_t Index(int i, int j, int k) const { return (int64_t(k) * Dims[1] + j) * Dims[0] + i; }
};

/// The samples: per lattice point the tetrahedron holding it (-1: outside the drawn mesh) and,
/// where one does, the mesh's scalar there (TetMesh::Points4's u, a fraction of ScalarRange) and,
/// with a separate opacity array, its opacity scalar (a fraction of OpacityRange); 0 elsewhere.
struct LatticeSamples
{
  std::vector<int64_t> Tet;
  std::vector<double> Scalar;
  std::vector<double> Opacity; ///< empty without a separate opacity array
};

/// Samples `mesh` at every point of `lattice` on vtkSMPTools' threads (psi::Parallel), in blocks
/// of tetrahedra after each of which `progress` (if given) hears the fraction done.
PSIVOLUMECORE_EXPORT LatticeSamples SampleOnLattice(const TetMesh& mesh, const Lattice& lattice,
  const std::function<void(double)>& progress = nullptr);

/// Barycentric coordinates of p in the tetrahedron (a, b, c, d): l[1..3] solve
/// [b-a, c-a, d-a] l = p - a (Cramer's rule), l[0] = 1 - l[1] - l[2] - l[3]. False for a
/// degenerate tetrahedron (no volume).
PSIVOLUMECORE_EXPORT bool Barycentric(const double a[3], const double b[3], const double c[3],
  const double d[3], const double p[3], double l[4]);

} // namespace psi

#endif
