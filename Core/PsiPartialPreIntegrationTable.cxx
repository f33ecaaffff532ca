#include "PsiPartialPreIntegrationTable.h"

#include "PsiIntegration.h"
#include "PsiParallel.h"
#include "PsiStopwatch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace psi
{

double WarpOfGamma(double gamma)
{
  return 1.0 - std::sqrt(std::max(1.0 - gamma, 0.0));
}

double TauDOfWarp(double u)
{
  return u >= 1.0 ? std::numeric_limits<double>::infinity() : 1.0 / ((1.0 - u) * (1.0 - u)) - 1.0;
}

double PartialPreIntegrationTable::Lookup(double gammab, double gammaf) const
{
  auto coord = [this](double g, int& i0, double& w)
  {
    const double x = WarpOfGamma(std::min(std::max(g, 0.0), 1.0)) * (this->N - 1);
    i0 = std::min(static_cast<int>(std::floor(x)), this->N - 2);
    w = x - i0;
  };
  int i, j;
  double wi, wj;
  coord(gammab, i, wi);
  coord(gammaf, j, wj);
  const float* v = this->Values.data();
  const double a = v[j * N + i] * (1 - wi) + v[j * N + i + 1] * wi;
  const double b = v[(j + 1) * N + i] * (1 - wi) + v[(j + 1) * N + i + 1] * wi;
  return a * (1 - wj) + b * wj;
}

PartialPreIntegrationTable BuildPsiTable(int n)
{
  const Stopwatch clock;
  PartialPreIntegrationTable t;
  t.N = std::max(n, 2);
  t.Values.resize(static_cast<size_t>(t.N) * t.N);
  // Rows on vtkSMPTools' threads (psi::Parallel): as many as the process allows, not one per core
  // in each MPI rank.
  psi::Parallel(
    [&t]
    {
      vtkSMPTools::For(0, t.N,
        [&t](vtkIdType first, vtkIdType last)
        {
          for (vtkIdType j = first; j < last; ++j)
          {
            const double taufD = TauDOfWarp(static_cast<double>(j) / (t.N - 1));
            for (int i = 0; i < t.N; ++i)
            {
              const double taubD = TauDOfWarp(static_cast<double>(i) / (t.N - 1));
              t.Values[static_cast<size_t>(j) * t.N + i] = static_cast<float>(Psi(taubD, taufD));
            }
          }
        });
    });
  t.BuildSeconds = clock.Seconds();
  return t;
}

const PartialPreIntegrationTable& GetDefaultPsiTable()
{
  static const PartialPreIntegrationTable table = BuildPsiTable(512);
  return table;
}

} // namespace psi
