#include "PsiIntegrationMethods.h"

#include "PsiPartialPreIntegrationTable.h"

#include <boost/math/special_functions/erf.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace psi
{

Segment AttenuationSegment(const TFSegment& s)
{
  Segment g;
  g.Lf = s.Lf;
  g.Lb = s.Lb;
  g.tauf = s.af / s.unit;
  g.taub = s.ab / s.unit;
  g.D = s.D;
  return g;
}

double Erfcx(double x)
{
  // e^{x^2} erfc(x) in double: Boost's erfc up to x = 26 (e^{676} and erfc(26) ~ 1e-296 are
  // both representable), then the asymptotic series (Abramowitz-Stegun 7.1.23), whose first
  // omitted term is below 1e-14 there. (The GLSL version uses the float-grade fit of Moreland
  // 2004 dissertation Eqs. 3.23-3.24, as Williams, Max & Stein 1998 do.)
  if (x < 26)
  {
    return std::exp(x * x) * boost::math::erfc(x);
  }
  const double r = 1 / (2 * x * x);
  return 0.5641895835477563 / x * (1 - r * (1 - 3 * r * (1 - 5 * r * (1 - 7 * r * (1 - 9 * r)))));
}

double Dawson(double x)
{
  // Rybicki's method (Numerical Recipes §6.10; Moreland 2004 dissertation Appendix B.3 uses
  // h = 0.4 and 6 terms, ~2e-7). Here h = 0.2 and 17 terms: the sampling error e^{-(pi/2h)^2}
  // and the truncation are both below 1e-16; small |x| by its Taylor series.
  const double ax = std::abs(x);
  if (ax < 0.2)
  {
    // F(x) = sum_n (-1)^n 2^n x^{2n+1} / (2n+1)!!
    double term = x, sum = x;
    const double x2 = x * x;
    for (int n = 1; n < 12; ++n)
    {
      term *= -2 * x2 / (2 * n + 1);
      sum += term;
    }
    return sum;
  }
  constexpr double H = 0.2;
  constexpr int Terms = 17;
  const int n0 = 2 * static_cast<int>(std::floor(0.5 * ax / H + 0.5));
  const double xp = ax - n0 * H;
  double e1 = std::exp(2 * H * xp);
  const double e2 = e1 * e1;
  double d1 = n0 + 1, d2 = d1 - 2, sum = 0;
  for (int i = 0; i < Terms; ++i)
  {
    const double c = std::exp(-((2 * i + 1) * H) * ((2 * i + 1) * H));
    sum += c * (e1 / d1 + 1 / (d2 * e1));
    d1 += 2;
    d2 -= 2;
    e1 *= e2;
  }
  // Rybicki: F(x) = lim_{h->0} (1/sqrt(pi)) sum_{n odd} e^{-(x - nh)^2} / n, here recentred at x'.
  const double r = 0.5641895835477563 * std::exp(-xp * xp) * sum;
  return x < 0 ? -r : r;
}

namespace
{
// M_n(b) = int_0^1 u^n e^{-bu} du: power series for small b, upward recurrence
// M_n = (n M_{n-1} - e^{-b}) / b from M_0 = (1 - e^{-b}) / b otherwise (stable for b >= 2, n <= 4).
double Moment(int n, double b)
{
  if (b < 2)
  {
    double sum = 0, term = 1; // term = (-b)^k / k!
    for (int k = 0; k < 40; ++k)
    {
      sum += term / (n + k + 1);
      term *= -b / (k + 1);
    }
    return sum;
  }
  const double eb = std::exp(-b);
  double m = -std::expm1(-b) / b;
  for (int i = 1; i <= n; ++i)
  {
    m = (i * m - eb) / b;
  }
  return m;
}
} // namespace

double PsiClosedForm(double taubD, double taufD)
{
  // Psi = int_0^1 exp(-b u - c u^2) du, b = tau_f D, c = (tau_b - tau_f) D / 2 (PsiIntegration.h).
  if (std::isnan(taubD) || std::isnan(taufD))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (std::isinf(taubD) || std::isinf(taufD))
  {
    return 0.0;
  }
  const double b = taufD, c = 0.5 * (taubD - taufD);
  const double zeta = std::exp(-(b + c)); // exp(-(tau_b + tau_f) D / 2)
  if (std::abs(c) < 1e-4 * std::max(1.0, b))
  {
    // Where the closed form cancels (tau_b ~ tau_f): the series in c around the homogeneous case
    // (Eq. 3.21), Psi = M0 - c M2 + c^2 M4 / 2 - ..., truncated after c^2 (error ~ |c|^3 / 42).
    return Moment(0, b) - c * Moment(2, b) + 0.5 * c * c * Moment(4, b);
  }
  const double rc = std::sqrt(std::abs(c));
  const double y0 = b / (2 * rc);
  if (c > 0)
  {
    // tau_b > tau_f, Eq. 3.25: sqrt(pi)/(2 sqrt(c)) [erfcx(y0) - zeta erfcx(y0 + sqrt(c))].
    return 0.886226925452758 / rc * (Erfcx(y0) - zeta * Erfcx(y0 + rc));
  }
  // tau_b < tau_f, Eq. 3.27: (1/sqrt(|c|)) [F(y0) - zeta F(y0 - sqrt(|c|))].
  return (Dawson(y0) - zeta * Dawson(y0 - rc)) / rc;
}

namespace
{
// Linear-luminance blend given Psi and zeta (Moreland 2004 dissertation Eq. 5.8 form, as in
// Appendix B.5/B.6).
Rgba Blend(const TFSegment& s, double psi, double zeta)
{
  Rgba out;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = s.Lf[k] * (1 - psi) + s.Lb[k] * (psi - zeta);
  }
  out[3] = 1 - zeta;
  return out;
}

// (1 - e^{-x}) / x with the x -> 0 limit.
double PsiHomogeneous(double x)
{
  return x < 1e-8 ? 1 - 0.5 * x : -std::expm1(-x) / x;
}

// Optical depth of D world units of constant transmittance `trans` = 1 - alpha per unit
// (Eq. 5.12). The methods combine transmittances, not opacities, which is exact near alpha = 1.
double DepthOfTransmittance(double trans, double D, double unit)
{
  const double t = std::min(std::max(trans, 0.0), 1.0);
  if (t <= 0.0)
  {
    return D > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  }
  return -std::log(t) * D / unit;
}

double Transmittance(double alpha)
{
  return std::max(1.0 - alpha, 0.0);
}
} // namespace

// The CPU integrators, one per method (the rows of the table below point at them).
namespace
{
// 1. Shirley-Tuchman: average luminance and attenuation (Moreland 2004 dissertation §3.2.2).
Rgba IntegrateAverageMethod(const TFSegment& s, const PartialPreIntegrationTable*)
{
  return IntegrateAverage(AttenuationSegment(s));
}

// 2. Partial pre-integration (Moreland & Angel 2004; Moreland 2004 dissertation §5.2): the Psi
// table when given, exact Psi otherwise.
Rgba IntegratePartialPreIntegration(const TFSegment& s, const PartialPreIntegrationTable* psiTable)
{
  const Segment g = AttenuationSegment(s);
  const double psi = psiTable ? psiTable->Lookup(GammaOf(g.taub * g.D), GammaOf(g.tauf * g.D))
                              : Psi(g.taub * g.D, g.tauf * g.D);
  return IntegrateWithPsi(g, psi);
}

// 3. Williams, Max & Stein 1998: Psi in closed form (Moreland 2004 dissertation Eq. 3.28). Also
// the exact value that 7. (Röttger et al. 2000 full pre-integration) tabulates.
Rgba IntegrateLinearExact(const TFSegment& s, const PartialPreIntegrationTable*)
{
  const Segment g = AttenuationSegment(s);
  return IntegrateWithPsi(g, PsiClosedForm(g.taub * g.D, g.tauf * g.D));
}

// 4. Average luminance and opacity (Wilhelms & van Gelder 1991), combined as transmittances.
Rgba IntegrateAverageOpacity(const TFSegment& s, const PartialPreIntegrationTable*)
{
  const double tauD =
    DepthOfTransmittance(0.5 * (Transmittance(s.ab) + Transmittance(s.af)), s.D, s.unit);
  const double alpha = -std::expm1(-tauD);
  Rgba out;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = 0.5 * (s.Lf[k] + s.Lb[k]) * alpha;
  }
  out[3] = alpha;
  return out;
}

// 5. Moreland 2004 dissertation §5.3.1, Appendix B.5: tau from the averaged opacity; Psi of a
// homogeneous segment.
Rgba IntegrateLinearLuminanceAverageOpacity(const TFSegment& s, const PartialPreIntegrationTable*)
{
  const double tauD =
    DepthOfTransmittance(0.5 * (Transmittance(s.ab) + Transmittance(s.af)), s.D, s.unit);
  const double zeta = std::exp(-tauD);
  return Blend(s, std::isinf(tauD) ? 0.0 : PsiHomogeneous(tauD), zeta);
}

// 6. Moreland 2004 dissertation §5.3.2, Appendix B.6: zeta from the parabola-corrected mean
// opacity (Eq. 5.13), Psi from the 0.27/0.73-weighted opacity (Eq. 5.14).
Rgba IntegrateLinearOpacityImproved(const TFSegment& s, const PartialPreIntegrationTable*)
{
  const double tb = Transmittance(s.ab), tf = Transmittance(s.af);
  const double zeta = std::exp(
    -DepthOfTransmittance(0.5 * (tb + tf) - 0.108165 * (tb - tf) * (tb - tf), s.D, s.unit));
  const double tau2D = DepthOfTransmittance(0.27 * tb + 0.73 * tf, s.D, s.unit);
  return Blend(s, std::isinf(tau2D) ? 0.0 : PsiHomogeneous(tau2D), zeta);
}

Rgba IntegrateNothing(const TFSegment&, const PartialPreIntegrationTable*)
{
  return Rgba{ { 0, 0, 0, 0 } };
}

constexpr OpticalModel Attenuation = OpticalModel::LinearAttenuation;
constexpr OpticalModel Opacity = OpticalModel::LinearOpacity;

// THE table of integration methods, in psi::Method order. Name is the panel text (the XML
// enumeration, checked by TestIntegrationMethods); GlslName is Shaders/<GlslName>.glsl (embedded
// by Rendering/CMakeLists.txt, which globs Shaders/PsiIntegrate*.glsl).
constexpr IntegrationMethodInfo Rows[] = {
  // Id, Name, GlslName, NeedsPsiTable, NeedsPreIntegrationTable, Model, Integrate,
  // SweepErrorBound, Reference
  { Method::Average, "Average", "PsiIntegrateAverage", false, false, Attenuation,
    IntegrateAverageMethod, 0.5, // bleeds back color through the front (dissertation Fig. 3.12)
    "Shirley & Tuchman 1990; Moreland 2004 dissertation §3.2.2, Eq. 3.16" },
  { Method::PartialPreIntegration, "Partial Pre-Integration", "PsiIntegratePartialPreIntegration",
    true, false, Attenuation, IntegratePartialPreIntegration, 2e-4, // Psi table lookup
    "Moreland & Angel 2004; Moreland 2004 dissertation §5.2" },
  { Method::LinearExact, "Linear Exact", "PsiIntegrateLinearExact", false, false, Attenuation,
    IntegrateLinearExact, 1e-9, // closed form in double
    "Williams, Max & Stein 1998; Moreland 2004 dissertation §3.2.3, Eq. 3.28" },
  { Method::AverageOpacity, "Average Opacity", "PsiIntegrateAverageOpacity", false, false, Opacity,
    IntegrateAverageOpacity, 0.5, "Wilhelms & van Gelder 1991; Moreland 2004 dissertation §5.3" },
  { Method::LinearLuminanceAverageOpacity, "Linear Luminance Average Opacity",
    "PsiIntegrateLinearLuminanceAverageOpacity", false, false, Opacity,
    IntegrateLinearLuminanceAverageOpacity, 0.2, // dissertation Fig. 5.7
    "Moreland 2004 dissertation §5.3.1, Appendix B.5" },
  { Method::LinearOpacityImproved, "Linear Opacity Improved", "PsiIntegrateLinearOpacityImproved",
    false, false, Opacity, IntegrateLinearOpacityImproved, 0.1, // dissertation Fig. 5.9
    "Moreland 2004 dissertation §5.3.2, Eqs. 5.13-5.14, Appendix B.6" },
  { Method::FullPreIntegration, "Full Pre-Integration", "PsiIntegrateFullPreIntegration", false,
    true, Attenuation, IntegrateLinearExact,
    1e-9, // evaluated exactly here; the table's own error is tested with the table
    "Röttger, Kraus & Ertl 2000" },
};

constexpr bool RowsInEnumOrder()
{
  for (size_t i = 0; i < std::size(Rows); ++i)
  {
    if (static_cast<size_t>(Rows[i].Id) != i)
    {
      return false;
    }
  }
  return true;
}
static_assert(std::size(Rows) == static_cast<size_t>(Method::Count),
  "one row of the integration-method table per psi::Method value");
static_assert(RowsInEnumOrder(), "the rows of the integration-method table follow psi::Method");

constexpr IntegrationMethodInfo UnknownRow = { Method::Count, "Unknown", "", false, false,
  Attenuation, IntegrateNothing, 0.0, "" };
} // namespace

const std::vector<IntegrationMethodInfo>& IntegrationMethodTable()
{
  static const std::vector<IntegrationMethodInfo> table(std::begin(Rows), std::end(Rows));
  return table;
}

int NumberOfIntegrationMethods()
{
  return static_cast<int>(std::size(Rows));
}

const IntegrationMethodInfo* FindIntegrationMethod(int value)
{
  return value >= 0 && value < NumberOfIntegrationMethods() ? &IntegrationMethodTable()[value]
                                                            : nullptr;
}

const IntegrationMethodInfo* FindIntegrationMethod(const std::string& name)
{
  for (const IntegrationMethodInfo& info : IntegrationMethodTable())
  {
    if (name == info.Name)
    {
      return &info;
    }
  }
  return nullptr;
}

const IntegrationMethodInfo& GetIntegrationMethodInfo(Method m)
{
  const IntegrationMethodInfo* info = FindIntegrationMethod(static_cast<int>(m));
  return info ? *info : UnknownRow;
}

const char* MethodName(Method m)
{
  return GetIntegrationMethodInfo(m).Name;
}

bool UsesLinearOpacity(Method m)
{
  return GetIntegrationMethodInfo(m).Model == OpticalModel::LinearOpacity;
}

Rgba Integrate(Method m, const TFSegment& s, const PartialPreIntegrationTable* psiTable)
{
  return GetIntegrationMethodInfo(m).Integrate(s, psiTable);
}

} // namespace psi
