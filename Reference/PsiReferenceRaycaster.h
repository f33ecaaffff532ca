// PsiReferenceRaycaster: an exact CPU ray integration of a tetrahedral mesh, the reference that
// GPU images are measured against.
//
// Each pixel's ray starts on the near plane (so a camera inside the mesh is handled) and is
// intersected with every tetrahedron whose screen box covers the pixel (exact ray / face-plane
// clipping in double precision). Within a tetrahedron the scalar is linear along the ray; the
// segment is split at every transfer-function breakpoint, so color and attenuation are linear on
// each piece and the piece is integrated exactly (Moreland & Angel 2004 Eq. 7 with Psi by
// quadrature, psi::Psi). Pieces are composited front to back, then over the background. Translucent
// surface layers are composited at their depths, the segments split there.
#ifndef PsiReferenceRaycaster_h
#define PsiReferenceRaycaster_h

#include "PsiVolumeCoreModule.h"

#include <array>
#include <functional>
#include <vector>

namespace psi
{

/// A translucent unlit surface: where a ray crosses one of its triangles, the layer
/// (Opacity * Color, Opacity) is composited at that depth, between the volume in front of it and
/// the volume behind it.
struct ReferenceSurface
{
  std::vector<std::array<std::array<double, 3>, 3>> Triangles; ///< world coordinates
  std::array<double, 3> Color{ { 1, 1, 1 } };
  double Opacity = 0.5;
};

struct ReferenceScene
{
  std::vector<std::array<double, 3>> Points; ///< world coordinates
  std::vector<double> Scalars;               ///< one per point
  std::vector<std::array<int, 4>> Tets;
  /// Transfer function: luminance rgb and attenuation tau at scalar s.
  std::function<void(double s, double rgbTau[4])> Transfer;
  /// Scalars where the transfer function is not linear (control points, table samples).
  std::vector<double> Breakpoints;
  /// Translucent surfaces intermixed with the volume.
  std::vector<ReferenceSurface> Surfaces;
};

struct ReferenceCamera
{
  int Width = 64, Height = 64;
  /// Row-major inverse of (projection * view): normalized device coordinates -> world.
  std::array<double, 16> NdcToWorld{};
  /// Optional per-pixel window depth (0..1) of opaque geometry (row-major from the bottom row);
  /// empty means none. Rays stop there.
  std::vector<float> OpaqueDepth;
  std::array<double, 3> Background{ { 0, 0, 0 } };
  /// Optional per-pixel opaque color (rgb per pixel) shown behind the volume instead of the
  /// background where OpaqueDepth < 1.
  std::vector<float> OpaqueColor;
};

/// Renders rgb (3 doubles per pixel, rows from the bottom) in [0, 1] (not clamped).
std::vector<double> RenderReference(const ReferenceScene& scene, const ReferenceCamera& camera);

/// The segment [t0, t1] of a pixel's ray inside one tetrahedron and the scalar s0, s1 at its ends
/// (linear in between). t is the distance along the ray from the near plane.
struct ReferencePiece
{
  double t0, t1, s0, s1;
};

/// Each pixel's pieces (one list per pixel, rows from the bottom), unsorted: the rays and the
/// exact ray / face-plane clipping that RenderReference integrates, before it splits a piece at
/// the breakpoints and the surfaces. Opaque geometry does not shorten them.
std::vector<std::vector<ReferencePiece>> ReferencePixelPieces(
  const ReferenceScene& scene, const ReferenceCamera& camera);

} // namespace psi

#endif
