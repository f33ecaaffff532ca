#include "PsiPreIntegrationTable.h"

#include "PsiIntegration.h"
#include "PsiParallel.h"
#include "PsiPartialPreIntegrationTable.h"
#include "PsiStopwatch.h"
#include "PsiTransferFunctionTable.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace psi
{

double PreIntegrationLengthAxis::Index(double l) const
{
  if (!(l > 0))
  {
    return 0;
  }
  const double x = l / this->MinLength;
  const double k =
    x < 1 ? x : 1 + std::log(x) * (this->Samples - 2) / std::log(this->MaxLength / this->MinLength);
  return std::min(k, static_cast<double>(this->Samples - 1));
}

double PreIntegrationLengthAxis::Length(int k) const
{
  if (k <= 0)
  {
    return 0;
  }
  if (k >= this->Samples - 1)
  {
    return this->MaxLength;
  }
  return this->MinLength *
    std::pow(this->MaxLength / this->MinLength, (k - 1.0) / (this->Samples - 2));
}

void PreIntegrationLengthAxis::ShaderUniform(float u[4]) const
{
  u[0] = static_cast<float>(1 / this->MinLength);
  u[1] = static_cast<float>((this->Samples - 2) / std::log(this->MaxLength / this->MinLength));
  u[2] = static_cast<float>(this->Samples - 1);
  u[3] = static_cast<float>(1.0 / this->Samples);
}

PreIntegrationLengthAxis MakePreIntegrationLengthAxis(double minEdge, double maxEdge, int samples)
{
  PreIntegrationLengthAxis a;
  a.Samples = std::max(samples, 3);
  a.MaxLength = maxEdge > 0 && std::isfinite(maxEdge) ? maxEdge : 1;
  const double lo = 1e-4 * a.MaxLength, hi = 1e-2 * a.MaxLength;
  a.MinLength = minEdge > 0 ? std::min(std::max(0.1 * minEdge, lo), hi) : lo;
  return a;
}

void PreIntegrationTable::Lookup(double sf, double sb, double D, double out[4]) const
{
  const int ns = this->ScalarSamples, nd = this->LengthSamples;
  auto coord = [](double x, int n, int& i0, double& w)
  {
    x = std::min(std::max(x, 0.0), static_cast<double>(n - 1));
    i0 = std::min(static_cast<int>(x), n - 2);
    w = x - i0;
  };
  const double span = this->Range[1] - this->Range[0];
  int i, j, k;
  double wi, wj, wk;
  coord((sf - this->Range[0]) / span * (ns - 1), ns, i, wi);
  coord((sb - this->Range[0]) / span * (ns - 1), ns, j, wj);
  coord(this->Axis.Index(D), nd, k, wk);
  for (int c = 0; c < 4; ++c)
  {
    double v = 0;
    for (int dk = 0; dk < 2; ++dk)
    {
      for (int dj = 0; dj < 2; ++dj)
      {
        for (int di = 0; di < 2; ++di)
        {
          const double w = (dk ? wk : 1 - wk) * (dj ? wj : 1 - wj) * (di ? wi : 1 - wi);
          v +=
            w * this->Rgba[4 * ((static_cast<size_t>(k + dk) * ns + (j + dj)) * ns + (i + di)) + c];
        }
      }
    }
    out[c] = v;
  }
}

PreIntegrationTable BuildPreIntegrationTable(const TransferFunctionTable& tf,
  const PartialPreIntegrationTable& psi, const PreIntegrationLengthAxis& axis, int scalarSamples)
{
  const Stopwatch clock;
  PreIntegrationTable t;
  t.ScalarSamples = std::max(scalarSamples, 2);
  t.Axis = axis;
  t.Axis.Samples = std::max(axis.Samples, 3);
  t.LengthSamples = t.Axis.Samples;
  t.Range[0] = tf.Range[0];
  t.Range[1] = tf.Range[1];
  const int ns = t.ScalarSamples, nd = t.LengthSamples;
  t.Rgba.assign(4 * static_cast<size_t>(ns) * ns * nd, 0.0f);
  // Transfer-function samples between two table scalars: pieces where the table is linear.
  const double tfStep = (tf.Range[1] - tf.Range[0]) / std::max(tf.Size - 1, 1);
  const double sStep = (t.Range[1] - t.Range[0]) / (ns - 1);

  auto work = [&](vtkIdType first, vtkIdType last)
  {
    std::vector<double> L(4 * (MaxPiecesPerEntry + 1));
    for (int j = static_cast<int>(first); j < last; ++j) // back scalar
    {
      for (int i = 0; i < ns; ++i) // front scalar
      {
        const double sf = t.Range[0] + i * sStep, sb = t.Range[0] + j * sStep;
        const int crossings = tfStep > 0 ? static_cast<int>(std::abs(sb - sf) / tfStep) + 1 : 1;
        const int pieces = std::min(crossings, MaxPiecesPerEntry);
        for (int p = 0; p <= pieces; ++p)
        {
          tf.Lookup(sf + (sb - sf) * p / pieces, &L[4 * p]);
        }
        for (int k = 0; k < nd; ++k)
        {
          const double d = t.Axis.Length(k) / pieces;
          Rgba acc{ { 0, 0, 0, 0 } };
          for (int p = 0; p < pieces && acc[3] < 1 - 1e-7; ++p) // front to back
          {
            Segment seg;
            const double* f = &L[4 * p];
            const double* b = &L[4 * (p + 1)];
            seg.Lf = { { f[0], f[1], f[2] } };
            seg.Lb = { { b[0], b[1], b[2] } };
            seg.tauf = f[3];
            seg.taub = b[3];
            seg.D = d;
            const double psiValue = psi.Lookup(GammaOf(seg.taub * d), GammaOf(seg.tauf * d));
            acc = Over(acc, IntegrateWithPsi(seg, psiValue));
          }
          float* o = &t.Rgba[4 * ((static_cast<size_t>(k) * ns + j) * ns + i)];
          for (int c = 0; c < 4; ++c)
          {
            o[c] = static_cast<float>(acc[c]);
          }
        }
      }
    }
  };
  // Rows of back scalars on vtkSMPTools' threads (psi::Parallel), in chunks small enough that
  // the costly rows (far from the diagonal: more pieces) spread over the threads.
  psi::Parallel([&] { vtkSMPTools::For(0, ns, std::max(1, ns / 64), work); });
  t.BuildSeconds = clock.Seconds();
  return t;
}

} // namespace psi
