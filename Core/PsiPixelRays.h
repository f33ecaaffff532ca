// PsiPixelRays: the view-space ray through each pixel as an affine function of the pixel's window
// coordinates, so that a fragment shader forms its ray with two multiply-adds per vector instead
// of unprojecting its pixel through the inverse projection.
//
// A pixel (x, y) (window coordinates of its center, gl_FragCoord) has normalized device
// coordinates (2x/W - 1, 2y/H - 1); its point at device depth z is the homogeneous
// h = DCVC (ndc_x, ndc_y, z, 1), linear in (x, y). The ray is X(t) = O(x, y) + t S(x, y):
//  - perspective: O = 0 (the eye) and S = h(-1).xyz / c, with the constant c chosen so that S
//    points into the view and, for VTK's frusta (where h.z does not depend on x, y), S.z = -1:
//    t is then the view depth. S is affine in (x, y) for any projective DCVC, without dividing by
//    h.w per pixel.
//  - parallel: O = h(-1).xyz / h.w, the pixel's point on the near plane, and S the constant
//    direction from the near to the far plane, scaled to S.z = -1.
// Either way one of O and S is constant, which PsiRaySegments{GS,FS}.glsl rely on: a face plane
// n . X = w is met at t = (w - n . O) / (n . S), a ratio of a constant and an affine function of
// (x, y).
#ifndef PsiPixelRays_h
#define PsiPixelRays_h

#include "PsiVolumeCoreModule.h"

namespace psi
{

struct PSIVOLUMECORE_EXPORT PixelRays
{
  /// O(x, y) = Origin[0] + x Origin[1] + y Origin[2]; S likewise from Step.
  double Origin[3][3] = {};
  double Step[3][3] = {};

  /// The ray of the pixel whose center has window coordinates (x, y).
  void At(double x, double y, double origin[3], double step[3]) const;
};

/// The pixel rays of a viewport of `width` x `height` pixels for the inverse projection `dcvc`
/// (clip -> view, row-major as vtkMatrix4x4).
PSIVOLUMECORE_EXPORT PixelRays PixelRaysOf(
  const double dcvc[16], bool parallel, int width, int height);

} // namespace psi

#endif
