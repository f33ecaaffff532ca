#include "PsiCellCenterDepthSort.h"

#include "PsiParallel.h"

#include "vtkSMPTools.h"

#include <cstring>

namespace psi
{
namespace
{
// Maps a float onto uint32 so that unsigned order equals float order
// (sign-magnitude flip).
uint32_t OrderedBits(float f)
{
  uint32_t u;
  std::memcpy(&u, &f, sizeof(u));
  return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}
} // namespace

std::vector<float> ComputeCentroids(const float* points4, TetCells tets, size_t numTets)
{
  std::vector<float> c(3 * numTets);
  Parallel(
    [&]
    {
      vtkSMPTools::For(0, static_cast<vtkIdType>(numTets),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType t = begin; t < end; ++t)
          {
            float s[3] = { 0, 0, 0 };
            for (int v = 0; v < 4; ++v)
            {
              const float* p = points4 + 4 * static_cast<size_t>(tets(t, v));
              s[0] += p[0];
              s[1] += p[1];
              s[2] += p[2];
            }
            c[3 * t + 0] = 0.25f * s[0];
            c[3 * t + 1] = 0.25f * s[1];
            c[3 * t + 2] = 0.25f * s[2];
          }
        });
    });
  return c;
}

void SortBackToFront(const std::vector<float>& centroids, const double eye[3], bool parallel,
  std::vector<uint32_t>& order)
{
  const size_t n = centroids.size() / 3;
  // Key: ~(distance bits) in the high word so that ascending order is farthest
  // first; the cell id in the low word makes the order deterministic.
  std::vector<uint64_t> keys(n);
  Parallel(
    [&]
    {
      const float e[3] = { static_cast<float>(eye[0]), static_cast<float>(eye[1]),
        static_cast<float>(eye[2]) };
      vtkSMPTools::For(0, static_cast<vtkIdType>(n),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            const float* c = &centroids[3 * i];
            float d;
            if (parallel)
            {
              d = c[0] * e[0] + c[1] * e[1] + c[2] * e[2];
            }
            else
            {
              const float dx = c[0] - e[0], dy = c[1] - e[1], dz = c[2] - e[2];
              d = dx * dx + dy * dy + dz * dz;
            }
            keys[i] = (static_cast<uint64_t>(~OrderedBits(d)) << 32) | static_cast<uint64_t>(i);
          }
        });
      vtkSMPTools::Sort(keys.begin(), keys.end());
      order.resize(n);
      vtkSMPTools::For(0, static_cast<vtkIdType>(n),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            order[i] = static_cast<uint32_t>(keys[i] & 0xffffffffu);
          }
        });
    });
}

} // namespace psi
