// PsiPreIntegrationTable: full pre-integration (Röttger, Kraus & Ertl 2000): premultiplied color and opacity of a segment as a 3D table over (front scalar, back
// scalar, length), built for one transfer function.
//
// Each entry integrates the transfer function along the linear scalar path from s_f to s_b: the
// path is cut into pieces on which the sampled transfer function is linear (at most
// MaxPiecesPerEntry, evenly in s), each piece is integrated exactly for linear luminance and
// attenuation (partial pre-integration, psi::PsiTable), and the pieces are composited front to
// back. Lengths are sampled linearly on [0, MaxLength] (the longest tetrahedron edge bounds every
// segment). The table must be rebuilt whenever the transfer function changes.
#ifndef PsiPreIntegrationTable_h
#define PsiPreIntegrationTable_h

#include "PsiVolumeCoreModule.h"

#include <vector>

namespace psi
{
struct PsiTable;
struct TransferFunctionTable;

struct PSIVOLUMECORE_EXPORT PreIntegrationTable
{
  int ScalarSamples = 0, LengthSamples = 0;
  double Range[2] = { 0, 1 };
  double MaxLength = 1;
  /// RGBA, premultiplied: Rgba[4 * ((k * Ns + j) * Ns + i)], i: front scalar, j: back, k: length.
  std::vector<float> Rgba;
  double BuildSeconds = 0;

  /// Trilinear lookup as the GPU's linear filter does it (for tests).
  void Lookup(double sf, double sb, double D, double out[4]) const;
};

constexpr int MaxPiecesPerEntry = 32;

PSIVOLUMECORE_EXPORT PreIntegrationTable BuildPreIntegrationTable(
  const TransferFunctionTable& tf, const PsiTable& psi, double maxLength, int scalarSamples = 128,
  int lengthSamples = 32);

} // namespace psi

#endif
