// PsiReferenceMedia: the exact reference of several volumes that may share space, each a medium
// with its own mesh and transfer function (a psi::ReferenceScene each). Along each pixel's ray
// the pieces of every medium (psi::ReferencePixelPieces) are merged: the ray is cut at every
// piece's ends, at every medium's transfer-function breakpoints and at the surface layers. On a
// stretch where one medium is alone it is integrated exactly as RenderReference integrates it
// (Moreland & Angel 2004 Eq. 7); where several overlap, their attenuations add and so do their
// emissions (psi::IntegrateReferenceMedia, by quadrature). Disjoint media give the image of their
// union drawn as one scene.
//
// Each medium's mesh must be conforming (its tetrahedra share no volume): on a ray, a medium
// contributes the one piece that covers a stretch.
#ifndef PsiReferenceMedia_h
#define PsiReferenceMedia_h

#include "PsiReferenceRaycaster.h"

#include <vector>

namespace psi
{
/// Renders rgb (3 doubles per pixel, rows from the bottom) in [0, 1] (not clamped): `media`
/// intermixed, with the surfaces of all of them, in front of the camera's opaque geometry.
std::vector<double> RenderReferenceMedia(
  const std::vector<const ReferenceScene*>& media, const ReferenceCamera& camera);
} // namespace psi

#endif
