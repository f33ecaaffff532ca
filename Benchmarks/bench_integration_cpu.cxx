// Benchmark (not a test): what each integration method costs on the CPU and how accurate it is.
// Prints, per row of psi::IntegrationMethodTable(), ns per segment (1M random segments of
// Moreland's sweep domain) and the max / mean error over Moreland's sweeps (Moreland 2004
// dissertation Figs. 6.5-6.11: D = 0.001, 0.1, 1, 100 over the (alpha_f, alpha_b) plane, back
// luminance 1, front 0), each against the reference of its optical model. A method that needs a
// pre-integration table (Röttger, Kraus & Ertl 2000) is timed and measured through one.
// `--csv` prints machine-readable rows for Benchmarks/bench_integration.py.
#include "PsiIntegrationMethods.h"
#include "PsiPartialPreIntegrationTable.h"
#include "PsiPreIntegrationTable.h"
#include "PsiRampTable.h"
#include "PsiReferenceIntegrals.h"
#include "PsiTransferFunctionTable.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

int main(int argc, char* argv[])
{
  const bool csv = argc > 1 && std::strcmp(argv[1], "--csv") == 0;
  const psi::PartialPreIntegrationTable& table = psi::GetDefaultPsiTable();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  const int N = 1000000;
  std::vector<psi::TFSegment> segs(N);
  for (auto& s : segs)
  {
    s.af = U(rng);
    s.ab = U(rng);
    s.Lf = { { U(rng), U(rng), U(rng) } };
    s.Lb = { { U(rng), U(rng), U(rng) } };
    s.D = std::pow(10.0, 5 * U(rng) - 3);
  }
  // Full pre-integration: a lookup in a table built for a transfer function, whose build is
  // timed separately (it is paid on every transfer-function edit).
  const psi::TransferFunctionTable tf = psitest::RampTable({ 0, 0, 1, 0 }, { 1, 0.5f, 0, 1 });
  const psi::PreIntegrationTable pre =
    psi::BuildPreIntegrationTable(tf, table, psi::MakePreIntegrationLengthAxis(0, 100.0));
  // For its accuracy: a table for L(s) = s, tau(s) = s on [0, 1], lengths up to 1; a sweep point
  // (alpha_f, alpha_b, D) is the segment from s = alpha_f to s = alpha_b.
  psi::TransferFunctionTable ramp = tf;
  for (int i = 0; i < ramp.Size; ++i)
  {
    const float s = float(i) / (ramp.Size - 1);
    const float v[4] = { s, s, s, s };
    std::copy(v, v + 4, &ramp.Rgba[4 * i]);
  }
  const psi::PreIntegrationTable rampTable =
    psi::BuildPreIntegrationTable(ramp, table, psi::MakePreIntegrationLengthAxis(0, 1.0));

  if (csv)
  {
    std::printf(
      "method,ns_per_segment,max_err_D0.001,max_err_D0.1,max_err_D1,max_err_D100,mean_err,"
      "psi_table,pre_integration_table,optical_model\n");
  }
  else
  {
    std::printf(
      "Psi table %dx%d built in %.3f s; full pre-integration table %dx%dx%d built in %.3f s\n\n",
      table.N, table.N, table.BuildSeconds, pre.ScalarSamples, pre.ScalarSamples, pre.LengthSamples,
      pre.BuildSeconds);
    std::printf("%-34s %10s %10s %10s %10s %10s %10s\n", "method", "ns/segment", "max D=.001",
      "max D=0.1", "max D=1", "max D=100", "mean err");
  }
  for (const psi::IntegrationMethodInfo& info : psi::IntegrationMethodTable())
  {
    double sink = 0;
    const auto t0 = std::chrono::steady_clock::now();
    if (info.NeedsPreIntegrationTable)
    {
      for (const auto& s : segs)
      {
        double c[4];
        pre.Lookup(s.af, s.ab, s.D, c);
        sink += c[0];
      }
    }
    else
    {
      for (const auto& s : segs)
      {
        sink += info.Integrate(s, &table)[0];
      }
    }
    const double ns =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / N;
    double maxErr[4], meanErr = 0;
    int count = 0, di = 0;
    for (double D : { 0.001, 0.1, 1.0, 100.0 })
    {
      maxErr[di] = 0;
      if (info.NeedsPreIntegrationTable && D > rampTable.Axis.MaxLength)
      {
        maxErr[di++] = -1; // beyond the table's lengths: not applicable
        continue;
      }
      for (int i = 0; i < 24; ++i)
      {
        for (int j = 0; j < 24; ++j)
        {
          psi::TFSegment s;
          s.af = (i + 0.5) / 24;
          s.ab = (j + 0.5) / 24;
          s.Lf = { { 0, 0, 0 } };
          s.Lb = { { 1, 1, 1 } };
          s.D = D;
          psi::Rgba r = psi::IntegrateReferenceFor(info.Id, s);
          psi::Rgba c = info.Integrate(s, &table);
          if (info.NeedsPreIntegrationTable)
          {
            // through the table; the exact value of the same segment of the ramp
            double v[4];
            rampTable.Lookup(s.af, s.ab, D, v);
            c = { { v[0], v[1], v[2], v[3] } };
            psi::Segment g;
            g.Lf = { { s.af, s.af, s.af } };
            g.Lb = { { s.ab, s.ab, s.ab } };
            g.tauf = s.af;
            g.taub = s.ab;
            g.D = D;
            r = psi::IntegrateReference(g);
          }
          double e = 0;
          for (int k = 0; k < 4; ++k)
          {
            e = std::max(e, std::abs(c[k] - r[k]));
          }
          maxErr[di] = std::max(maxErr[di], e);
          meanErr += e;
          ++count;
        }
      }
      ++di;
    }
    meanErr /= count;
    if (csv)
    {
      std::printf("%s,%.2f,%.3e,%.3e,%.3e,%.3e,%.3e,%d,%d,%s\n", info.Name, ns, maxErr[0],
        maxErr[1], maxErr[2], maxErr[3], meanErr, info.NeedsPsiTable ? 1 : 0,
        info.NeedsPreIntegrationTable ? 1 : 0,
        info.Model == psi::OpticalModel::LinearOpacity ? "linear_opacity" : "linear_attenuation");
    }
    else
    {
      std::printf("%-34s %10.1f", info.Name, ns);
      for (double e : maxErr)
      {
        if (e < 0)
        {
          std::printf(" %10s", "n/a");
        }
        else
        {
          std::printf(" %10.2e", e);
        }
      }
      std::printf(" %10.2e\n", meanErr);
    }
    if (sink == 12345.678)
    {
      std::printf(" ");
    }
  }
  return 0;
}
