// PsiIsosurfaceList: the isosurfaces to draw, normalized once when they are set (GL-free):
// finite values only, ascending, a repeated value keeping its first entry's opacity, opacities
// clamped to [0, 1], at most MaxCount surfaces.
#ifndef PsiIsosurfaceList_h
#define PsiIsosurfaceList_h

#include "PsiVolumeCoreModule.h"

#include <cstddef>
#include <vector>

namespace psi
{
struct PSIVOLUMECORE_EXPORT IsosurfaceList
{
  /// The largest number of isosurfaces drawn; more are dropped (counted in Dropped).
  static constexpr int MaxCount = 32;

  std::vector<double> Values;   ///< ascending, distinct, finite
  std::vector<float> Opacities; ///< of each value, in [0, 1]
  size_t Dropped = 0;           ///< distinct finite values beyond MaxCount

  /// values[i] with opacities[i], or `defaultOpacity` where opacities has no entry i.
  static IsosurfaceList Normalize(
    const std::vector<double>& values, const std::vector<double>& opacities, double defaultOpacity);

  int Count() const { return static_cast<int>(this->Values.size()); }
  bool Empty() const { return this->Values.empty(); }
};
} // namespace psi

#endif
