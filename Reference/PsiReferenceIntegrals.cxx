#include "PsiReferenceIntegrals.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace psi
{

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
    auto g = [&](R u)
    {
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

Rgba IntegrateReferenceMedia(const std::vector<Segment>& media)
{
  using R = long double;
  Rgba out{ { 0, 0, 0, 0 } };
  if (media.empty() || !(media[0].D > 0))
  {
    return out;
  }
  // As IntegrateReference, u in [0, 1] from the front, with the sums of the media:
  //   T(u) = D sum_k (tau_fk u + (tau_bk - tau_fk) u^2 / 2),
  //   emission density D sum_k tau_k(u) L_k(u) exp(-T(u)).
  const R D = media[0].D;
  R tf = 0, tb = 0;
  for (const Segment& m : media)
  {
    tf += m.tauf;
    tb += m.taub;
  }
  const R umax = TruncationPoint<R>(D * tf, D * (tb - tf) / 2, R(46));
  using GK = boost::math::quadrature::gauss_kronrod<R, 61>;
  for (int c = 0; c < 3; ++c)
  {
    auto g = [&](R u)
    {
      R emission = 0;
      for (const Segment& m : media)
      {
        const R tau = m.tauf + (R(m.taub) - m.tauf) * u;
        emission += tau * (m.Lf[c] + (R(m.Lb[c]) - m.Lf[c]) * u);
      }
      const R T = D * (tf * u + (tb - tf) * u * u / 2);
      return D * emission * std::exp(-T);
    };
    out[c] = static_cast<double>(GK::integrate(g, R(0), umax, 15, R(1e-14)));
  }
  out[3] = static_cast<double>(-std::expm1(-D * (tf + tb) / 2));
  return out;
}

namespace
{
// Opacity 1 over the whole segment (D > 0). The color is (Moreland's dissertation §5.3, Eq. 5.12)
//   C = int_0^D tau(s) L(s) exp(-int_0^s tau(t) dt) ds,  tau(s) = -ln(1 - alpha(s)) / unit,
// whose weight w(s) = tau(s) exp(-int_0^s tau) is the density of 1 - T(s), T(s) the
// transmittance from the entry to s. With alpha = 1, tau is infinite: T(s) = 0 for every s > 0,
// so 1 - T jumps from 0 to 1 at s = 0, w is a unit impulse there and C = L(0) = Lf, alpha = 1.
// (The limit of alpha = 1 - eps, tau = -ln(eps) / unit: w = tau e^{-tau s} has mass
// 1 - eps^{D/unit} -> 1 and mean depth below 1/tau -> 0.) The quadrature below would multiply
// tau = inf by exp(-inf) = 0 instead.
Rgba FullyOpaque(const TFSegment& s)
{
  return Rgba{ { s.Lf[0], s.Lf[1], s.Lf[2], 1.0 } };
}
} // namespace

Rgba IntegrateReferenceLinearOpacity(const TFSegment& s)
{
  using R = long double;
  Rgba out{ { 0, 0, 0, 0 } };
  if (!(s.D > 0))
  {
    return out;
  }
  const R D = s.D / s.unit; // in unit distances
  const R af = std::min(std::max(s.af, 0.0), 1.0), ab = std::min(std::max(s.ab, 0.0), 1.0);
  if (af >= 1 && ab >= 1)
  {
    return FullyOpaque(s);
  }
  auto tau = [&](R u) { // per unit distance, u from the front
    const R a = af + (ab - af) * u;
    return a >= 1 ? std::numeric_limits<R>::infinity() : -std::log1p(-a);
  };
  using GK = boost::math::quadrature::gauss_kronrod<R, 31>;
  // Optical depth from the front to u: D int_0^u -ln(1 - alpha(s)) ds with alpha linear, in closed
  // form through F(w) = w ln w - w, w = 1 - alpha (no method under test uses this form).
  const R k = ab - af;
  auto F = [](R w) { return w > 0 ? w * std::log(w) - w : R(0); };
  auto depth = [&](R u)
  {
    if (u <= 0)
    {
      return R(0);
    }
    if (std::abs(k) < 1e-7L)
    {
      return -D * u * std::log1p(-(af + 0.5L * k * u)); // error O(k^2)
    }
    return D / k * (F(1 - af - k * u) - F(1 - af)); // d/du F(w(u)) = -k ln w
  };
  // alpha = 1 at an end makes tau infinite only at that point: -ln(1 - alpha) is integrable, the
  // optical depth stays finite, and Gauss-Kronrod nodes never sit on the end points.
  for (int k = 0; k < 3; ++k)
  {
    const R lf = s.Lf[k], lb = s.Lb[k];
    auto g = [&](R u) { return D * tau(u) * (lf + (lb - lf) * u) * std::exp(-depth(u)); };
    out[k] = static_cast<double>(GK::integrate(g, R(0), R(1), 15, R(1e-12)));
  }
  out[3] = static_cast<double>(-std::expm1(-depth(R(1))));
  return out;
}

Rgba IntegrateReferenceFor(Method m, const TFSegment& s)
{
  return UsesLinearOpacity(m) ? IntegrateReferenceLinearOpacity(s)
                              : IntegrateReference(AttenuationSegment(s));
}

} // namespace psi
