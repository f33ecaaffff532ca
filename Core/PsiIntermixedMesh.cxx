#include "PsiIntermixedMesh.h"

#include "PsiTetConnectivity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace psi
{
namespace
{
// Point i of `mesh` in the world: its unshifted coordinates placed by the row-major `m`.
std::array<double, 3> WorldPoint(const TetMesh& mesh, const std::array<double, 16>& m, size_t i)
{
  const float* p = &mesh.Points4[4 * i];
  const double x[3] = { p[0] + mesh.Shift[0], p[1] + mesh.Shift[1], p[2] + mesh.Shift[2] };
  std::array<double, 3> w;
  for (int r = 0; r < 3; ++r)
  {
    w[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
  return w;
}

// The world bounds of the points the volumes' cells use (empty: all zero), each point placed once.
void CellPointWorldBounds(const std::vector<IntermixedVolume>& volumes, double b[6])
{
  const double inf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
  {
    b[2 * k] = inf;
    b[2 * k + 1] = -inf;
  }
  for (const IntermixedVolume& v : volumes)
  {
    std::vector<char> used(v.Mesh->NumberOfPoints(), 0);
    const TetCells cells = v.Mesh->Cells();
    for (size_t t = 0; t < v.Mesh->NumberOfTets(); ++t)
    {
      for (int c = 0; c < 4; ++c)
      {
        used[cells(t, c)] = 1;
      }
    }
    for (size_t i = 0; i < used.size(); ++i)
    {
      if (!used[i])
      {
        continue;
      }
      const std::array<double, 3> w = WorldPoint(*v.Mesh, v.ModelToWorld, i);
      for (int k = 0; k < 3; ++k)
      {
        b[2 * k] = std::min(b[2 * k], w[k]);
        b[2 * k + 1] = std::max(b[2 * k + 1], w[k]);
      }
    }
  }
  if (!(b[0] <= b[1]))
  {
    std::fill(b, b + 6, 0.0);
  }
}
} // namespace

TetMesh IntermixMeshes(const std::vector<IntermixedVolume>& volumes, int samples)
{
  TetMesh m;
  double b[6];
  CellPointWorldBounds(volumes, b);
  for (int k = 0; k < 3; ++k)
  {
    m.Shift[k] = 0.5 * (b[2 * k] + b[2 * k + 1]);
    m.Bounds[2 * k] = b[2 * k] - m.Shift[k];
    m.Bounds[2 * k + 1] = b[2 * k + 1] - m.Shift[k];
  }
  const bool opacity = std::any_of(volumes.begin(), volumes.end(),
    [](const IntermixedVolume& v) { return !v.Mesh->Opacity.empty(); });
  const int n = static_cast<int>(volumes.size());
  for (int k = 0; k < n; ++k)
  {
    const TetMesh& v = *volumes[k].Mesh;
    const uint32_t base = static_cast<uint32_t>(m.NumberOfPoints());
    for (size_t i = 0; i < v.NumberOfPoints(); ++i)
    {
      const std::array<double, 3> w = WorldPoint(v, volumes[k].ModelToWorld, i);
      const double u = v.Points4[4 * i + 3];
      m.Points4.insert(m.Points4.end(),
        { static_cast<float>(w[0] - m.Shift[0]), static_cast<float>(w[1] - m.Shift[1]),
          static_cast<float>(w[2] - m.Shift[2]),
          static_cast<float>(SlotScalar(k, n, samples, u)) });
      if (opacity)
      {
        const double o = v.Opacity.empty() ? u : v.Opacity[i];
        m.Opacity.push_back(static_cast<float>(SlotScalar(k, n, samples, o)));
      }
    }
    const TetCells cells = v.Cells();
    for (size_t t = 0; t < v.NumberOfTets(); ++t)
    {
      for (int c = 0; c < 4; ++c)
      {
        m.Tets.push_back(base + cells(t, c));
      }
    }
    m.NonTetCells += v.NonTetCells;
    m.NonFiniteTets += v.NonFiniteTets;
    m.CellScalars = m.CellScalars || v.CellScalars;
  }
  MeasureEdgeLengths(m);
  return m;
}

TransferFunctionTable IntermixTables(const std::vector<TransferFunctionTable>& tables)
{
  TransferFunctionTable all;
  for (const TransferFunctionTable& t : tables)
  {
    all.Rgba.insert(all.Rgba.end(), t.Rgba.begin(), t.Rgba.end());
    all.Size += t.Size;
  }
  return all; // Range and OpacityRange [0, 1]: slot scalars
}

TransferFunctionNodes IntermixNodes(const std::vector<TransferFunctionNodes>& nodes,
  const std::vector<std::array<double, 2>>& ranges, int samples)
{
  TransferFunctionNodes all;
  const int n = static_cast<int>(nodes.size());
  for (int k = 0; k < n; ++k)
  {
    for (double s : nodes[k].Scalars)
    {
      all.Scalars.push_back(SlotScalar(k, n, samples, UnitScalar(ranges[k].data(), s)));
    }
    all.Rgba.insert(all.Rgba.end(), nodes[k].Rgba.begin(), nodes[k].Rgba.end());
    all.MaxDeviation = std::max(all.MaxDeviation, nodes[k].MaxDeviation);
  }
  return all;
}

std::vector<float> IntermixOpacityPrefixes(const std::vector<std::vector<float>>& prefixes)
{
  std::vector<float> all;
  float before = 0;
  for (const std::vector<float>& p : prefixes)
  {
    for (float count : p)
    {
      all.push_back(before + count);
    }
    before = all.empty() ? 0.0f : all.back();
  }
  return all;
}

std::vector<int32_t> WeldedFaceNeighbors(const TetMesh& mesh)
{
  // each point's id: the first point at exactly its position (the same world point of two
  // volumes has the same float coordinates after the same shift)
  const size_t np = mesh.NumberOfPoints();
  std::vector<uint32_t> byPosition(np);
  std::iota(byPosition.begin(), byPosition.end(), 0u);
  const auto key = [&mesh](uint32_t i)
  {
    const float* p = &mesh.Points4[4 * size_t(i)];
    return std::make_tuple(p[0], p[1], p[2]);
  };
  std::sort(byPosition.begin(), byPosition.end(),
    [&key](uint32_t a, uint32_t b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  std::vector<uint32_t> welded(np);
  for (size_t k = 0; k < np; ++k)
  {
    const bool same = k > 0 && key(byPosition[k]) == key(byPosition[k - 1]);
    welded[byPosition[k]] = same ? welded[byPosition[k - 1]] : byPosition[k];
  }
  std::vector<uint32_t> tets(mesh.Tets.size());
  for (size_t i = 0; i < tets.size(); ++i)
  {
    tets[i] = welded[mesh.Tets[i]];
  }
  std::vector<int32_t> neighbors;
  ComputeTetNeighbors(TetCells(tets.data()), mesh.NumberOfTets(), np, neighbors);
  return neighbors;
}

} // namespace psi
