#include "PsiIntegration.h"

#include <boost/math/quadrature/gauss.hpp>

#include <cmath>
#include <limits>

namespace psi
{
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
  // 512^2 table take a few hundredths of a second.
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
    out[k] = s.Lb[k] * (psi - zeta) + s.Lf[k] * (1.0 - psi); // Moreland & Angel 2004 Eq. 7, I0 = 0
  }
  out[3] = -std::expm1(-0.5 * (taubD + taufD));
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
