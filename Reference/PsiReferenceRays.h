// PsiReferenceRays: what the exact references (PsiReferenceRaycaster, PsiReferenceMedia) share
// along one pixel's ray: the ray itself, where opaque geometry stops it, the translucent surface
// layers it crosses, and what shows behind the volume.
#ifndef PsiReferenceRays_h
#define PsiReferenceRays_h

#include "PsiIntegration.h"
#include "PsiReferenceRaycaster.h"
#include "PsiVec3.h"

#include <array>
#include <vector>

namespace psi
{
/// Homogeneous transform of (x, y, z, 1) by a row-major matrix, divided by w.
Vec3 TransformPoint(const std::array<double, 16>& m, double x, double y, double z);

/// The inverse of a row-major 4x4 matrix (Gauss-Jordan, partial pivoting).
std::array<double, 16> InverseMatrix(const std::array<double, 16>& m);

/// The ray of pixel (i, j): from the near plane `o` along the unit direction `d`, `len` to the
/// far plane.
struct PixelRay
{
  Vec3 o, d;
  double len;
};
PixelRay RayOf(const ReferenceCamera& cam, int i, int j);

/// The distance along pixel (i, j)'s `ray` to the camera's opaque geometry; 1e300 where none.
double OpaqueDistance(const ReferenceCamera& cam, const PixelRay& ray, int i, int j);

/// A translucent surface crossed at distance T, its premultiplied color.
struct Layer
{
  double T;
  Rgba Color;
};
/// The crossings of the ray o + t d (0 < t < tMax) with the surfaces' triangles, nearest first
/// (Moeller and Trumbore's ray/triangle test).
std::vector<Layer> SurfaceLayers(
  const std::vector<ReferenceSurface>& surfaces, const Vec3& o, const Vec3& d, double tMax);

/// The segment of length D between scalars sa and sb through the scene's transfer function
/// (luminance and attenuation at each end; linear in between when no breakpoint lies between).
Segment TransferSegment(const ReferenceScene& sc, double sa, double sb, double D);

/// `acc` (premultiplied, front to back) over what shows behind the volume at pixel (i, j): the
/// camera's opaque color there, or its background.
Vec3 OverBehind(const ReferenceCamera& cam, int i, int j, const Rgba& acc);
} // namespace psi

#endif
