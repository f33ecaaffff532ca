// PsiRampTable: a sampled transfer function whose color and attenuation vary linearly over
// s in [0, 1], from `low` (s = 0) to `high` (s = 1) (RGB, then tau), for the tests and
// benchmarks of the tables built from one (Röttger et al. 2000's pre-integration table).
#ifndef PsiRampTable_h
#define PsiRampTable_h

#include "PsiTransferFunctionTable.h"

#include <array>

namespace psitest
{
inline psi::TransferFunctionTable RampTable(
  const std::array<float, 4>& low, const std::array<float, 4>& high, int size = 256)
{
  psi::TransferFunctionTable tf;
  tf.Size = size;
  tf.Range[0] = 0;
  tf.Range[1] = 1;
  tf.Rgba.resize(4 * tf.Size);
  for (int i = 0; i < tf.Size; ++i)
  {
    const double s = double(i) / (tf.Size - 1);
    for (int c = 0; c < 4; ++c)
    {
      tf.Rgba[4 * i + c] = static_cast<float>((1 - s) * low[c] + s * high[c]);
    }
  }
  return tf;
}
} // namespace psitest

#endif
