#include "PsiIntegration.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <limits>

namespace psi
{
namespace
{
// Where the exponent E(u) = b u + c u^2 (b = tau_f D, c = (tau_b D - tau_f D)/2) reaches `cut`.
// E is non-decreasing on [0, 1] because E'(u) = b (1 - u) + tau_b D u >= 0.
template <typename Real>
Real TruncationPoint(Real b, Real c, Real cut)
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
} // namespace

double Psi(double taubD, double taufD)
{
  if (std::isnan(taubD) || std::isnan(taufD))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (std::isinf(taubD) || std::isinf(taufD))
  {
    return 0.0; // the integrand is 0 for every u > 0
  }
  const double b = taufD;
  const double c = 0.5 * (taubD - taufD);
  const double umax = TruncationPoint(b, c, 42.0); // exp(-42) < 1e-18
  // On [0, umax] the exponent runs monotonically from 0 to at most 42: the integrand is smooth and
  // a fixed 30-point Gauss-Legendre rule is exact to ~1e-15 (measured against adaptive
  // long-double quadrature over the whole gamma domain) at a fixed cost, which is what makes a
  // 1024^2 table take a fraction of a second.
  auto f = [b, c](double u) { return std::exp(-(b * u + c * u * u)); };
  return boost::math::quadrature::gauss<double, 30>::integrate(f, 0.0, umax);
}

double GammaOf(double tauD)
{
  if (std::isinf(tauD))
  {
    return 1.0;
  }
  return tauD / (tauD + 1.0);
}

double TauDOf(double gamma)
{
  return gamma >= 1.0 ? std::numeric_limits<double>::infinity() : gamma / (1.0 - gamma);
}

double Zeta(double taubD, double taufD)
{
  return std::exp(-0.5 * (taubD + taufD));
}

Rgba IntegrateAverage(const Segment& s)
{
  const double tau = 0.5 * (s.tauf + s.taub);
  // 1 - exp(-x) via expm1 keeps full relative precision for tiny tau D.
  const double alpha = -std::expm1(-tau * s.D);
  Rgba out;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = 0.5 * (s.Lf[k] + s.Lb[k]) * alpha;
  }
  out[3] = alpha;
  return out;
}

Rgba IntegrateWithPsi(const Segment& s, double psi)
{
  const double taubD = s.taub * s.D, taufD = s.tauf * s.D;
  const double zeta = Zeta(taubD, taufD);
  Rgba out;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = s.Lb[k] * (psi - zeta) + s.Lf[k] * (1.0 - psi); // seed 000 Eq. 7 with I0 = 0
  }
  out[3] = -std::expm1(-0.5 * (taubD + taufD));
  return out;
}

Rgba IntegrateReference(const Segment& s)
{
  using R = long double;
  Rgba out{ { 0, 0, 0, 0 } };
  if (!(s.D > 0))
  {
    return out;
  }
  // Normalized coordinate u in [0, 1] from the front; optical depth so far
  //   T(u) = D int_0^u tau = D (tau_f u + (tau_b - tau_f) u^2 / 2) (exact for linear tau).
  // Emission density: D tau(u) L(u) exp(-T(u)).
  const R D = s.D, tf = s.tauf, tb = s.taub;
  const R umax = TruncationPoint<R>(D * tf, D * (tb - tf) / 2, R(46));
  using GK = boost::math::quadrature::gauss_kronrod<R, 61>;
  for (int k = 0; k < 3; ++k)
  {
    const R lf = s.Lf[k], lb = s.Lb[k];
    auto g = [&](R u) {
      const R tau = tf + (tb - tf) * u;
      const R L = lf + (lb - lf) * u;
      const R T = D * (tf * u + (tb - tf) * u * u / 2);
      return D * tau * L * std::exp(-T);
    };
    out[k] = static_cast<double>(GK::integrate(g, R(0), umax, 15, R(1e-14)));
  }
  // Total optical depth by quadrature of tau as well (not the closed form under test).
  auto t = [&](R u) { return D * (tf + (tb - tf) * u); };
  const R T1 = GK::integrate(t, R(0), R(1), 5, R(1e-18));
  out[3] = static_cast<double>(-std::expm1(-T1));
  return out;
}

Rgba Over(const Rgba& f, const Rgba& b)
{
  Rgba out;
  for (int k = 0; k < 4; ++k)
  {
    out[k] = f[k] + (1.0 - f[3]) * b[k];
  }
  return out;
}

} // namespace psi
