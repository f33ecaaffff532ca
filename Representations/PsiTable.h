// PsiTable: the partial pre-integration table Psi(gamma_b, gamma_f) (seed 000 §4, Eq. 12).
//
// gamma = tau D / (tau D + 1) maps tau D in [0, inf) onto [0, 1), so one finite table covers every
// cell size. Samples sit at gamma = i / (N - 1), i = 0..N-1, both ends included (gamma = 1 is the
// limit tau D -> inf, where Psi = 0), so bilinear filtering with texel-center coordinates
//   texcoord = (gamma (N - 1) + 0.5) / N
// interpolates between exact samples over the whole domain.
#ifndef PsiTable_h
#define PsiTable_h

#include "PsiVolumeRepresentationsModule.h"

#include <vector>

namespace psi
{

struct PSIVOLUMEREPRESENTATIONS_EXPORT PsiTable
{
  int N = 0;
  /// Row-major: Values[j * N + i] = Psi(gamma_b = i/(N-1), gamma_f = j/(N-1)).
  std::vector<float> Values;
  double BuildSeconds = 0;

  /// Bilinear lookup exactly as the GPU's linear filter does it (for tests and CPU use).
  double Lookup(double gammab, double gammaf) const;
};

/// Builds the table by quadrature (psi::Psi), using all hardware threads.
PSIVOLUMEREPRESENTATIONS_EXPORT PsiTable BuildPsiTable(int n);

/// One table per process, built on first use at the default resolution (1024, or the
/// PSI_TABLE_SIZE environment variable).
PSIVOLUMEREPRESENTATIONS_EXPORT const PsiTable& GetDefaultPsiTable();

} // namespace psi

#endif
