// PsiPreIntegrationTable: full pre-integration (Röttger, Kraus & Ertl 2000): premultiplied color
// and opacity of a segment as a 3D table over (front scalar, back scalar, length), built for one
// transfer function.
//
// Each entry integrates the transfer function along the linear scalar path from s_f to s_b: the
// path is cut into pieces on which the sampled transfer function is linear (at most
// MaxPiecesPerEntry, evenly in s), each piece is integrated exactly for linear luminance and
// attenuation (partial pre-integration, psi::PartialPreIntegrationTable), and the pieces are
// composited front to back. Lengths are sampled on a logarithmic axis (PreIntegrationLengthAxis),
// so that short cells next to long ones keep their relative accuracy. The table must be rebuilt
// whenever the transfer function changes.
#ifndef PsiPreIntegrationTable_h
#define PsiPreIntegrationTable_h

#include "PsiVolumeCoreModule.h"

#include <vector>

namespace psi
{
struct PartialPreIntegrationTable;
struct TransferFunctionTable;

/// The table's length axis: a logarithmic scale of the segment length, as Kraus, Qiao & Ebert
/// ("Projecting Tetrahedra without Rendering Artifacts", 2004) use for their pre-integrated
/// lookup table, so that a segment keeps its relative accuracy whatever its length. Sample 0 is
/// l = 0, exact (a segment of no length is transparent); samples 1 .. Samples-1 are geometric from
/// MinLength to MaxLength; between 0 and MinLength the index is linear in l. Index() is the plain
/// function the shader evaluates (Shaders/PsiIntegrateFullPreIntegration.glsl, with the uniform
/// ShaderUniform()), testable without GL.
struct PSIVOLUMECORE_EXPORT PreIntegrationLengthAxis
{
  double MinLength = 1e-4, MaxLength = 1;
  int Samples = 32;

  /// Fractional sample index of length l, clamped to [0, Samples - 1]; NaN and l <= 0 give 0.
  double Index(double l) const;
  /// Length at sample k (0 for k = 0).
  double Length(int k) const;
  /// (1 / MinLength, (Samples - 2) / ln(MaxLength / MinLength), Samples - 1, 1 / Samples): with
  /// x = l * u[0], index = min(x < 1 ? x : 1 + ln(x) * u[1], u[2]), texture coordinate
  /// (index + 0.5) * u[3].
  void ShaderUniform(float u[4]) const;
};

/// The axis for a mesh whose edges are between minEdge and maxEdge (the longest edge bounds every
/// segment): MinLength a tenth of the shortest edge (corner segments are shorter than any edge),
/// but at most four decades and at least two below maxEdge, so that the geometric step stays
/// fine (ratio 10^(4/30) = 1.36 between samples at most with 32 samples).
PSIVOLUMECORE_EXPORT PreIntegrationLengthAxis MakePreIntegrationLengthAxis(
  double minEdge, double maxEdge, int samples = 32);

struct PSIVOLUMECORE_EXPORT PreIntegrationTable
{
  int ScalarSamples = 0, LengthSamples = 0;
  double Range[2] = { 0, 1 };
  PreIntegrationLengthAxis Axis;
  /// RGBA, premultiplied: Rgba[4 * ((k * Ns + j) * Ns + i)], i: front scalar, j: back, k: length.
  std::vector<float> Rgba;
  double BuildSeconds = 0;

  /// Trilinear lookup as the GPU's linear filter does it (for tests).
  void Lookup(double sf, double sb, double D, double out[4]) const;
};

constexpr int MaxPiecesPerEntry = 32;

/// The table over `axis` (its Samples are the length samples).
PSIVOLUMECORE_EXPORT PreIntegrationTable BuildPreIntegrationTable(const TransferFunctionTable& tf,
  const PartialPreIntegrationTable& psi, const PreIntegrationLengthAxis& axis,
  int scalarSamples = 128);

} // namespace psi

#endif
