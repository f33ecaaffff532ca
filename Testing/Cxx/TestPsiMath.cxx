// GL-free tests of the math behind 'Psi Volume': the PTINT truth table and the fan it implies,
// Psi and the segment integrals against an independent quadrature, and the Psi table.
#include "PsiIntegration.h"
#include "PsiPartialPreIntegrationTable.h"
#include "PsiProjectionClasses.h"
#include "PsiReferenceIntegrals.h"
#include "PsiTestCheck.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{
double Area(const double* a, const double* b, const double* c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

double HullArea(const double x[4], const double y[4])
{
  // Andrew's monotone chain on 4 points.
  std::vector<std::pair<double, double>> p;
  for (int i = 0; i < 4; ++i)
  {
    p.emplace_back(x[i], y[i]);
  }
  std::sort(p.begin(), p.end());
  std::vector<std::pair<double, double>> h(8);
  int k = 0;
  auto cross = [](const auto& o, const auto& a, const auto& b)
  {
    return (a.first - o.first) * (b.second - o.second) -
      (a.second - o.second) * (b.first - o.first);
  };
  for (int i = 0; i < 4; ++i)
  {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0)
      --k;
    h[k++] = p[i];
  }
  for (int i = 2, t = k + 1; i >= 0; --i)
  {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0)
      --k;
    h[k++] = p[i];
  }
  double a = 0;
  for (int i = 0; i + 1 < k; ++i)
  {
    a += h[i].first * h[i + 1].second - h[i + 1].first * h[i].second;
  }
  return 0.5 * std::abs(a);
}

// The triangles the geometry shader emits for a class (same fans as Shaders/PsiVolumeGS.glsl),
// with the thick vertex computed in 2D; their total unsigned area must equal the hull's, and
// they must not overlap (sum of |areas| == hull area implies that for a fan inside the hull).
double FanArea(const psi::ProjectionClass& c, const double x[4], const double y[4])
{
  const auto& p = c.p;
  double P[4][2];
  for (int i = 0; i < 4; ++i)
  {
    P[i][0] = x[p[i]];
    P[i][1] = y[p[i]];
  }
  double T[2];
  double sum = 0;
  switch (c.cls)
  {
    case 1:
      T[0] = P[3][0];
      T[1] = P[3][1];
      sum = std::abs(Area(P[0], P[1], T)) + std::abs(Area(P[1], T, P[2])) +
        std::abs(Area(T, P[2], P[0]));
      break;
    case 2:
    {
      const double d1[2] = { P[1][0] - P[0][0], P[1][1] - P[0][1] };
      const double d2[2] = { P[3][0] - P[2][0], P[3][1] - P[2][1] };
      const double den = d1[0] * d2[1] - d1[1] * d2[0];
      const double e[2] = { P[2][0] - P[0][0], P[2][1] - P[0][1] };
      const double t = (e[0] * d2[1] - e[1] * d2[0]) / den;
      T[0] = P[0][0] + t * d1[0];
      T[1] = P[0][1] + t * d1[1];
      sum = std::abs(Area(P[0], P[2], T)) + std::abs(Area(P[2], T, P[1])) +
        std::abs(Area(T, P[1], P[3])) + std::abs(Area(P[3], P[0], T));
      break;
    }
    case 3:
      T[0] = P[3][0];
      T[1] = P[3][1];
      sum = std::abs(Area(P[1], P[2], T)) + std::abs(Area(P[2], T, P[0]));
      break;
    case 4:
      sum = std::abs(Area(P[0], P[1], P[2]));
      break;
  }
  return sum;
}

void TestTruthTable()
{
  psi::ProjectionClassTable table;
  std::string error;
  PSI_CHECK(psi::BuildProjectionClassTable(table, &error), "inconsistent table: %s", error.c_str());
  int count[5] = { 0, 0, 0, 0, 0 };
  for (const auto& e : table)
  {
    ++count[e.cls];
  }
  // Marroquim et al. 2006 §4.1: Wylie's 14 general cases, plus 24 class-3 and 12 class-4 cases.
  PSI_CHECK(count[1] + count[2] == 14, "general cases %d", count[1] + count[2]);
  PSI_CHECK(count[3] == 24, "class 3 cases %d", count[3]);
  PSI_CHECK(count[4] == 12, "class 4 cases %d", count[4]);

  // Random configurations, generic and on a coarse lattice (degenerate), classified through
  // the table must agree with direct geometric classification, and the fan must tile the hull.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  std::uniform_int_distribution<int> L(-3, 3);
  int checked = 0;
  for (int n = 0; n < 200000; ++n)
  {
    double x[4], y[4];
    for (int i = 0; i < 4; ++i)
    {
      x[i] = n % 2 ? U(rng) : L(rng);
      y[i] = n % 2 ? U(rng) : L(rng);
    }
    const psi::ProjectionClass direct = psi::ClassifyProjection(x, y);
    const psi::ProjectionClass& looked = table[psi::TruthTableIndex(x, y)];
    PSI_CHECK(
      direct.cls == looked.cls, "config %d: class %d vs table %d", n, direct.cls, looked.cls);
    if (looked.cls == 0)
    {
      continue;
    }
    const double hull = HullArea(x, y), fan = FanArea(looked, x, y);
    PSI_CHECK(std::abs(hull - fan) <= 1e-9 * std::max(1.0, hull),
      "config %d class %d: fan area %g vs hull %g", n, looked.cls, fan, hull);
    ++checked;
  }
  std::printf("truth table: %d/%d/%d/%d entries of class 1/2/3/4; %d random fans tile the hull\n",
    count[1], count[2], count[3], count[4], checked);
}

void TestPsi()
{
  // Homogeneous attenuation: Psi = (1 - e^-x) / x (Moreland & Angel 2004, constant-tau limit), over
  // 15 decades.
  double worst = 0;
  for (double x = 1e-9; x <= 1e6; x *= 3.7)
  {
    const double exact = -std::expm1(-x) / x;
    worst = std::max(worst, std::abs(psi::Psi(x, x) - exact) / exact);
  }
  PSI_CHECK(worst < 1e-12, "homogeneous Psi relative error %g", worst);
  PSI_CHECK(psi::Psi(0, 0) == 1.0, "Psi(0,0) = %g", psi::Psi(0, 0));
  PSI_CHECK(psi::Psi(INFINITY, 1) == 0.0 && psi::Psi(1, INFINITY) == 0.0, "Psi at infinity");
  PSI_CHECK(std::isnan(psi::Psi(NAN, 1)), "Psi(NaN) must be NaN, the caller's to contain");
  std::printf("Psi: homogeneous case exact to %.2g (relative) over tau D in [1e-9, 1e6]\n", worst);
}

void TestSegmentIntegrals()
{
  // Eq. 7 with exact Psi equals the independent long-double quadrature of the integral.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  double worstPsi = 0, worstAvgSmall = 0;
  for (int n = 0; n < 400; ++n)
  {
    psi::Segment s;
    for (int k = 0; k < 3; ++k)
    {
      s.Lf[k] = U(rng);
      s.Lb[k] = U(rng);
    }
    s.tauf = std::pow(10.0, 4 * U(rng) - 2);
    s.taub = std::pow(10.0, 4 * U(rng) - 2);
    s.D = std::pow(10.0, 4 * U(rng) - 2);
    const psi::Rgba ref = psi::IntegrateReference(s);
    const psi::Rgba p = psi::IntegrateWithPsi(s, psi::Psi(s.taub * s.D, s.tauf * s.D));
    for (int k = 0; k < 4; ++k)
    {
      worstPsi = std::max(worstPsi, std::abs(p[k] - ref[k]));
    }
    if (s.D * std::max(s.tauf, s.taub) < 1e-2)
    {
      const psi::Rgba a = psi::IntegrateAverage(s);
      for (int k = 0; k < 4; ++k)
      {
        worstAvgSmall = std::max(worstAvgSmall, std::abs(a[k] - ref[k]));
      }
    }
  }
  PSI_CHECK(worstPsi < 1e-10, "partial pre-integration (exact Psi) vs reference: %g", worstPsi);
  PSI_CHECK(worstAvgSmall < 1e-3, "average method for thin segments: %g", worstAvgSmall);

  // Hard cases: D = 0, tau = 0 at both ends, equal ends, huge tau D; finite output.
  psi::Segment s;
  s.Lf = { { 1, 0.5, 0.25 } };
  s.Lb = { { 0.25, 0.5, 1 } };
  s.D = 0;
  s.tauf = s.taub = 3;
  auto p = psi::IntegrateWithPsi(s, psi::Psi(0, 0));
  PSI_CHECK(p[0] == 0 && p[3] == 0, "D = 0 must be transparent: %g %g", p[0], p[3]);
  s.D = 1;
  s.tauf = s.taub = 0;
  p = psi::IntegrateWithPsi(s, psi::Psi(0, 0));
  PSI_CHECK(p[0] == 0 && p[3] == 0, "tau = 0 must be transparent: %g %g", p[0], p[3]);
  s.tauf = s.taub = 1e6;
  p = psi::IntegrateWithPsi(s, psi::Psi(1e6, 1e6));
  PSI_CHECK(std::abs(p[0] - 1.0) < 1e-5 && std::abs(p[3] - 1) < 1e-12,
    "opaque segment shows the front luminance: %g alpha %g", p[0], p[3]);
  std::printf("segments: Eq. 7 with exact Psi within %.2g of the quadrature reference\n", worstPsi);
}

void TestPsiTable()
{
  const psi::PartialPreIntegrationTable t = psi::BuildPsiTable(512);
  std::printf("Psi table 512^2 built in %.3f s\n", t.BuildSeconds);
  // Bilinear lookup error over the whole domain, including off-sample points and gamma -> 1.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  double worstInterior = 0, worstEdge = 0;
  for (int n = 0; n < 20000; ++n)
  {
    const bool edge = n < 200; // gamma_b within 1e-6 of 1: tau_b D > 1e6
    const double gb = edge ? 1 - 1e-6 * U(rng) : U(rng);
    const double gf = U(rng);
    const double exact = psi::Psi(psi::TauDOf(gb), psi::TauDOf(gf));
    double& worst = edge ? worstEdge : worstInterior;
    worst = std::max(worst, std::abs(t.Lookup(gb, gf) - exact));
  }
  // Uniform-gamma sampling (Moreland's) misses by 1.4e-2 near gamma_b = 1; the warped sampling
  // must stay far below one 8-bit step (3.9e-3) everywhere, and near 1e-5 off the extreme edge.
  PSI_CHECK(worstInterior < 2e-5, "Psi table (512^2) lookup error %g", worstInterior);
  PSI_CHECK(worstEdge < 5e-4, "Psi table (512^2) lookup error at tau_b D > 1e6: %g", worstEdge);
  std::printf("Psi table: max bilinear lookup error %.2g (%.2g where tau_b D > 1e6)\n",
    worstInterior, worstEdge);
  PSI_CHECK(t.Values[0] == 1.0f, "Psi(0,0) sample %g", t.Values[0]);
}
} // namespace

int main()
{
  TestTruthTable();
  TestPsi();
  TestSegmentIntegrals();
  TestPsiTable();
  return psitest::Report("TestPsiMath");
}
