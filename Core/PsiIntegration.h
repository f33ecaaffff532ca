// PsiIntegration: the volume rendering integral over one ray segment, as plain functions.
//
// Optical model (Moreland & Angel 2004 Eq. 1; Moreland 2004 dissertation ch. 3):
// emission is luminance times attenuation, so over a segment of length D entered at the front
//   I = I0 * zeta + integral_0^D L(t) tau(t) exp(-int_0^t tau) dt.
// With L and tau linear between the front (f) and back (b) values, Moreland & Angel 2004 Eq. 7
// gives
//   I = I0 * zeta + Lb (Psi - zeta) + Lf (1 - Psi),   alpha = 1 - zeta,
//   zeta = exp(-(tau_b + tau_f) D / 2)                     (Moreland & Angel 2004 Eq. 8)
//   Psi  = int_0^1 exp(-(tau_f D) u - (tau_b D - tau_f D) u^2 / 2) du
//          (Moreland & Angel 2004 Eq. 10, u measured from the front, i.e. the distance the light
//          still has to travel).
// tau comes from ParaView's opacity transfer function as opacity / ScalarOpacityUnitDistance, the
// convention of VTK's vtkUnstructuredGrid*RayIntegrator classes, so images are comparable.
#ifndef PsiIntegration_h
#define PsiIntegration_h

#include "PsiVolumeCoreModule.h"

#include <cmath>

#include <array>

namespace psi
{

using Rgb = std::array<double, 3>;
/// Premultiplied color and opacity of one segment (what is blended "over" what lies behind).
using Rgba = std::array<double, 4>;

/// Front/back samples of one segment: luminance L, attenuation tau (1/length), length D.
struct Segment
{
  Rgb Lf{ { 0, 0, 0 } }, Lb{ { 0, 0, 0 } };
  double tauf = 0, taub = 0;
  double D = 0;
};

/// Psi(tau_b D, tau_f D) by 30-point Gauss-Legendre quadrature (Boost.Math) on the part of
/// [0, 1] where the integrand exceeds 1e-18; accurate to ~1e-15 for any non-negative arguments,
/// including +inf (Psi = 0). Returns NaN for NaN input.
PSIVOLUMECORE_EXPORT double Psi(double taubD, double taufD);

/// gamma = tau D / (tau D + 1), the table coordinate of Moreland & Angel 2004 Eq. 11 (in [0, 1];
/// +inf -> 1).
PSIVOLUMECORE_EXPORT double GammaOf(double tauD);
/// Inverse of GammaOf: tau D = gamma / (1 - gamma).
PSIVOLUMECORE_EXPORT double TauDOf(double gamma);

/// zeta = exp(-(tau_b + tau_f) D / 2), Moreland & Angel 2004 Eq. 8.
PSIVOLUMECORE_EXPORT double Zeta(double taubD, double taufD);

/// Shirley-Tuchman average luminance and attenuation (Moreland 2004 dissertation §3.2): L and tau
/// taken as the mean of the two ends, alpha = 1 - exp(-tau D), color = L alpha.
PSIVOLUMECORE_EXPORT Rgba IntegrateAverage(const Segment& s);

/// Moreland & Angel 2004 Eq. 7 given a Psi value (exact Psi, or a table lookup): partial
/// pre-integration.
PSIVOLUMECORE_EXPORT Rgba IntegrateWithPsi(const Segment& s, double psi);

// Where the exponent E(u) = b u + c u^2 (b = tau_f D, c = (tau_b D - tau_f D)/2) reaches `cut`.
// E is non-decreasing on [0, 1] because E'(u) = b (1 - u) + tau_b D u >= 0.
template <typename Real>
inline Real TruncationPoint(Real b, Real c, Real cut)
{
  const Real e1 = b + c; // E(1) = (tau_b D + tau_f D) / 2
  if (e1 <= cut)
  {
    return 1;
  }
  const Real disc = b * b + 4 * c * cut;
  // Stable root of c u^2 + b u - cut = 0 (Numerical Recipes §5.6 form).
  const Real u = 2 * cut / (b + std::sqrt(disc > 0 ? disc : Real(0)));
  return u < 1 ? u : Real(1);
}

/// Over operator for premultiplied colors: front over back.
PSIVOLUMECORE_EXPORT Rgba Over(const Rgba& front, const Rgba& back);

} // namespace psi

#endif
