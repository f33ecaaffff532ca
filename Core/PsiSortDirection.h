// PsiSortDirection: which end of the visibility order comes first. Back-to-front ("over")
// compositing takes the farthest tetrahedron first; front-to-back ("under") compositing, which
// can stop where a pixel is already opaque, the nearest first. Both composite the same image:
// the ray integral splits at any point into a nearer and a farther part (Moreland's dissertation
// §2.2, Eq. 2.11 back to front with "over", Eq. 2.13 front to back with "under", §2.2.3).
#ifndef PsiSortDirection_h
#define PsiSortDirection_h

namespace psi
{
enum class SortDirection
{
  FarthestFirst,
  NearestFirst
};
} // namespace psi

#endif
