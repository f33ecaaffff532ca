// The hard cases for the segment integrals (zero length, also where the opacity is 1, zero and
// equal attenuations, tau D over 15 decades, alpha = 1 at an end, at both ends and just below,
// luminance outside [0, 1]), shared by the C++ and GLSL tests.
#ifndef PsiHardCases_h
#define PsiHardCases_h

#include "PsiIntegrationMethods.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace psitest
{
struct HardCase
{
  const char* Name;
  psi::TFSegment S;
  /// The error a method must stay within on this case where the case pins it down more tightly
  /// than the method's sweep bound; negative (or no function): the sweep bound.
  double (*Bound)(psi::Method m, const psi::TFSegment& s) = nullptr;
};

/// Opacity 1 over a whole segment of positive length: the ray takes the front luminance,
/// (Lf, 1) (psi::IntegrateReferenceLinearOpacity, from Moreland's dissertation §5.3, Eq. 5.12).
/// The methods blending linear luminance by Psi (§5.3.1-5.3.2) give it exactly (zeta = 0,
/// Psi = 0); Average Opacity gives the mean luminance, off by exactly |Lb - Lf| / 2; the
/// attenuation methods read alpha as tau and meet their sweep bounds.
inline double FullyOpaqueBound(psi::Method m, const psi::TFSegment& s)
{
  switch (m)
  {
    case psi::Method::LinearLuminanceAverageOpacity:
    case psi::Method::LinearOpacityImproved:
      return 0.0;
    case psi::Method::AverageOpacity:
      return 0.5 *
        std::max({ std::abs(s.Lb[0] - s.Lf[0]), std::abs(s.Lb[1] - s.Lf[1]),
          std::abs(s.Lb[2] - s.Lf[2]) });
    default:
      return -1.0;
  }
}

/// `floatInputs`: epsilons a float can represent (1e-7 instead of 1e-12 near 1).
inline std::vector<HardCase> HardCases(bool floatInputs)
{
  const double eps = floatInputs ? 1e-7 : 1e-12;
  auto seg = [](double af, double ab, double D, double lf = 0.2, double lb = 0.9)
  {
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
    { "alpha = 1 both ends, D > 0", seg(1.0, 1.0, 1.0), FullyOpaqueBound },
    { "alpha = 1 front, D = 0", seg(1.0, 0.3, 0.0) },
    { "alpha just below 1", seg(1 - 1e3 * eps, 1 - 1e4 * eps, 1.0) },
    { "luminance outside [0,1]", seg(0.3, 0.6, 1.5, -0.5, 3.0) },
    { "thickness 1e-7 of the mesh", seg(0.8, 0.9, 1e-7) },
  };
}
} // namespace psitest

#endif
