// PsiIntegration: the volume rendering integral over one ray segment, as plain functions.
//
// Optical model (Moreland & Angel 2004, seed 000 Eq. 1; Moreland's dissertation, seed 001 ch. 3):
// emission is luminance times attenuation, so over a segment of length D entered at the front
//   I = I0 * zeta + integral_0^D L(t) tau(t) exp(-int_0^t tau) dt.
// With L and tau linear between the front (f) and back (b) values, seed 000 Eq. 7 gives
//   I = I0 * zeta + Lb (Psi - zeta) + Lf (1 - Psi),   alpha = 1 - zeta,
//   zeta = exp(-(tau_b + tau_f) D / 2)                                           (seed 000 Eq. 8)
//   Psi  = int_0^1 exp(-(tau_f D) u - (tau_b D - tau_f D) u^2 / 2) du          (seed 000 Eq. 10,
//          u measured from the front, i.e. the distance the light still has to travel).
// tau comes from ParaView's opacity transfer function as opacity / ScalarOpacityUnitDistance, the
// convention of VTK's vtkUnstructuredGrid*RayIntegrator classes, so images are comparable.
#ifndef PsiIntegration_h
#define PsiIntegration_h

#include "PsiVolumeRepresentationsModule.h"

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
PSIVOLUMEREPRESENTATIONS_EXPORT double Psi(double taubD, double taufD);

/// gamma = tau D / (tau D + 1), the table coordinate of seed 000 Eq. 11 (in [0, 1]; +inf -> 1).
PSIVOLUMEREPRESENTATIONS_EXPORT double GammaOf(double tauD);
/// Inverse of GammaOf: tau D = gamma / (1 - gamma).
PSIVOLUMEREPRESENTATIONS_EXPORT double TauDOf(double gamma);

/// zeta = exp(-(tau_b + tau_f) D / 2), seed 000 Eq. 8.
PSIVOLUMEREPRESENTATIONS_EXPORT double Zeta(double taubD, double taufD);

/// Shirley-Tuchman average luminance and attenuation (seed 001 §3.2): L and tau taken as the
/// mean of the two ends, alpha = 1 - exp(-tau D), color = L alpha.
PSIVOLUMEREPRESENTATIONS_EXPORT Rgba IntegrateAverage(const Segment& s);

/// Seed 000 Eq. 7 given a Psi value (exact Psi, or a table lookup): partial pre-integration.
PSIVOLUMEREPRESENTATIONS_EXPORT Rgba IntegrateWithPsi(const Segment& s, double psi);

/// The reference: the integral itself, evaluated by nested adaptive quadrature in long double,
/// independent of Psi and of every closed form above. Slow; for tests and error measurement.
PSIVOLUMEREPRESENTATIONS_EXPORT Rgba IntegrateReference(const Segment& s);

/// Over operator for premultiplied colors: front over back.
PSIVOLUMEREPRESENTATIONS_EXPORT Rgba Over(const Rgba& front, const Rgba& back);

} // namespace psi

#endif
