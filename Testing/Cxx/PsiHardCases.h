// The hard cases for the segment integrals (zero length, also where the opacity is 1, zero and
// equal attenuations, tau D over 15 decades, alpha = 1 and just below, luminance outside [0, 1]),
// shared by the C++ and GLSL tests.
#ifndef PsiHardCases_h
#define PsiHardCases_h

#include "PsiIntegrationMethods.h"

#include <vector>

namespace psitest
{
struct HardCase
{
  const char* Name;
  psi::TFSegment S;
};

/// `floatInputs`: epsilons a float can represent (1e-7 instead of 1e-12 near 1).
inline std::vector<HardCase> HardCases(bool floatInputs)
{
  const double eps = floatInputs ? 1e-7 : 1e-12;
  auto seg = [](double af, double ab, double D, double lf = 0.2, double lb = 0.9) {
    psi::TFSegment s;
    s.af = af;
    s.ab = ab;
    s.D = D;
    s.Lf = { { lf, lf, lf } };
    s.Lb = { { lb, lb, lb } };
    return s;
  };
  return {
    { "D = 0", seg(0.5, 0.7, 0.0) },
    { "tau = 0 both ends", seg(0.0, 0.0, 3.0) },
    { "tau_b = tau_f exactly", seg(0.4, 0.4, 2.0) },
    { "tau_b = tau_f (1 + eps)", seg(0.4, 0.4 * (1 + eps), 2.0) },
    { "tau D = 1e-9", seg(1e-9, 2e-9, 1.0) },
    { "tau D = 1e6", seg(1.0, 0.5, 1e6) },
    { "alpha = 1 front", seg(1.0, 0.3, 1.0) },
    { "alpha = 1 back", seg(0.3, 1.0, 1.0) },
    { "alpha = 1 both ends, D = 0", seg(1.0, 1.0, 0.0) },
    { "alpha = 1 front, D = 0", seg(1.0, 0.3, 0.0) },
    { "alpha just below 1", seg(1 - 1e3 * eps, 1 - 1e4 * eps, 1.0) },
    { "luminance outside [0,1]", seg(0.3, 0.6, 1.5, -0.5, 3.0) },
    { "thickness 1e-7 of the mesh", seg(0.8, 0.9, 1e-7) },
  };
}
} // namespace psitest

#endif
