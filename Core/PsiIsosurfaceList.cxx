#include "PsiIsosurfaceList.h"

#include "PsiTetMesh.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace psi
{
IsosurfaceList IsosurfaceList::Normalize(
  const std::vector<double>& values, const std::vector<double>& opacities, double defaultOpacity)
{
  std::vector<std::pair<double, float>> list; // (value, opacity)
  for (size_t i = 0; i < values.size(); ++i)
  {
    const double v = values[i];
    const double o = i < opacities.size() ? opacities[i] : defaultOpacity;
    if (FiniteScalar(v))
    {
      list.emplace_back(
        v, static_cast<float>(std::isfinite(o) ? std::min(1.0, std::max(0.0, o)) : 1.0));
    }
  }
  using Entry = std::pair<double, float>;
  auto byValue = [](const Entry& a, const Entry& b) { return a.first < b.first; };
  auto sameValue = [](const Entry& a, const Entry& b) { return a.first == b.first; };
  std::stable_sort(list.begin(), list.end(), byValue);
  list.erase(std::unique(list.begin(), list.end(), sameValue), list.end());
  IsosurfaceList out;
  if (list.size() > static_cast<size_t>(MaxCount))
  {
    out.Dropped = list.size() - MaxCount;
    list.resize(MaxCount);
  }
  for (const auto& vo : list)
  {
    out.Values.push_back(vo.first);
    out.Opacities.push_back(vo.second);
  }
  return out;
}
} // namespace psi
