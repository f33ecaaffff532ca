// PartialPreIntegrationTable: the partial pre-integration table Psi(gamma_b, gamma_f) (Moreland &
// Angel 2004 §4, Eq. 12).
//
// gamma = tau D / (tau D + 1) maps tau D in [0, inf) onto [0, 1), so one finite table covers every
// cell size. Sampling gamma uniformly, as Moreland does, leaves a square-root singularity at the
// edge: for gamma_b -> 1, Psi ~ sqrt(pi / (2 tau_b D)) ~ sqrt(1 - gamma_b), which bilinear
// filtering misses by 1e-2 in the last texel (measured, 512^2 and 1024^2). The samples are
// therefore placed uniformly in the warped coordinate
//   u = 1 - sqrt(1 - gamma) = 1 - 1 / sqrt(tau D + 1),
// in which Psi is linear near the edge and still smooth near 0 (u ~ gamma / 2). Samples sit at
// u = i / (N - 1), both ends included (u = 1 is tau D -> inf, Psi = 0); bilinear filtering with
// texcoord = (u (N - 1) + 0.5) / N interpolates between exact samples over the whole domain.
#ifndef PsiPartialPreIntegrationTable_h
#define PsiPartialPreIntegrationTable_h

#include "PsiVolumeCoreModule.h"

#include <vector>

namespace psi
{

struct PSIVOLUMECORE_EXPORT PartialPreIntegrationTable
{
  int N = 0;
  /// Row-major: Values[j * N + i] = Psi(u_b = i/(N-1), u_f = j/(N-1)), u = WarpOfGamma(gamma).
  std::vector<float> Values;
  double BuildSeconds = 0;

  /// Bilinear lookup exactly as the GPU's linear filter does it (for tests and CPU use).
  double Lookup(double gammab, double gammaf) const;
};

/// u = 1 - sqrt(1 - gamma), the table coordinate.
PSIVOLUMECORE_EXPORT double WarpOfGamma(double gamma);
/// tau D at table coordinate u: (1 - u)^-2 - 1.
PSIVOLUMECORE_EXPORT double TauDOfWarp(double u);

/// Builds the table by quadrature (psi::Psi), using all hardware threads.
PSIVOLUMECORE_EXPORT PartialPreIntegrationTable BuildPsiTable(int n);

/// One table per process, built on first use at 512^2. With the warped samples 512^2 looks up
/// Psi within 2e-5 everywhere (TestPsiMath), far below an 8-bit step; a finer table costs build
/// time and memory for nothing an image shows (docs/decisions.md, "The Ψ table").
PSIVOLUMECORE_EXPORT const PartialPreIntegrationTable& GetDefaultPsiTable();

} // namespace psi

#endif
