// PsiProjectionClasses: the PTINT ternary truth table (Marroquim et al. 2006, Fig. 3 and §4.1).
//
// A tetrahedron's four projected vertices v0..v3 are classified by the signs of four 2D cross
// products (Marroquim et al. 2006, Fig. 3):
//   test1 = sign((v1-v0) x (v2-v0)) + 1      test2 = sign((v1-v0) x (v3-v0)) + 1
//   test3 = sign((v2-v0) x (v3-v0)) + 1      test4 = sign((v1-v2) x (v1-v3)) + 1
// and index = 27*test1 + 9*test2 + 3*test3 + test4 selects one of 81 table entries.
//
// Rather than typing the 81 entries by hand, the table is *derived*: every configuration of four
// points on a small integer lattice is classified geometrically (exact integer arithmetic), and the
// result is recorded under its sign index. A sign pattern that two configurations would classify
// differently is an error (reported by BuildProjectionClassTable; tested in Testing/Cxx).
//
// Class numbering follows Marroquim et al. 2006 (Fig. 1):
//   class 1: one vertex projects inside the triangle of the other three -> 3 triangles
//   class 2: two edges cross                                          -> 4 triangles
//   class 3: one vertex projects onto an edge (degenerate class 1/2)  -> 2 triangles
//   class 4: two vertices project onto the same point                  -> 1 triangle
//   class 0: all four on a line, or a sign pattern no configuration has -> nothing drawn
#ifndef PsiProjectionClasses_h
#define PsiProjectionClasses_h

#include "PsiVolumeCoreModule.h"

#include <array>
#include <string>

namespace psi
{

/// One entry of the ternary truth table. The permutation p gives vertex roles:
///  class 1: p[3] is the interior (thick) vertex, p[0..2] the silhouette triangle.
///  class 2: segment p[0]p[1] crosses segment p[2]p[3]; silhouette quad is p0,p2,p1,p3.
///  class 3: p[3] lies on segment p[0]p[1]; p[2] is the remaining vertex.
///  class 4: p[2] and p[3] coincide; p[0], p[1] are the others.
struct ProjectionClass
{
  int cls = 0;
  std::array<int, 4> p{ { 0, 1, 2, 3 } };
};

using ProjectionClassTable = std::array<ProjectionClass, 81>;

/// Index of the truth table for projected points (x[i], y[i]), computed with the tests of
/// Marroquim et al. 2006, Fig. 3. Exposed so the table can be checked against the GLSL code path.
PSIVOLUMECORE_EXPORT int TruthTableIndex(const double x[4], const double y[4]);

/// Classifies one configuration geometrically (no table); used to derive and to test the table.
PSIVOLUMECORE_EXPORT ProjectionClass ClassifyProjection(const double x[4], const double y[4]);

/// Derives the 81-entry table. On an inconsistency (which would be a bug), returns false and
/// describes it in *error.
PSIVOLUMECORE_EXPORT bool BuildProjectionClassTable(
  ProjectionClassTable& table, std::string* error = nullptr);

/// The table as built once per process.
PSIVOLUMECORE_EXPORT const ProjectionClassTable& GetProjectionClassTable();

/// Packs an entry into one int for a GLSL uniform array: cls | p0<<4 | p1<<6 | p2<<8 | p3<<10.
PSIVOLUMECORE_EXPORT int PackProjectionClass(const ProjectionClass& c);

/// The whole table packed so, as the geometry shader's `classTable` uniform takes it.
PSIVOLUMECORE_EXPORT const std::array<int, 81>& GetPackedProjectionClassTable();

} // namespace psi

#endif
