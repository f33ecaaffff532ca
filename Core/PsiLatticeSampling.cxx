#include "PsiLatticeSampling.h"

#include "PsiParallel.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>

namespace psi
{
namespace
{
// A lattice point counts as inside a tetrahedron when no barycentric coordinate is below -Slack:
// the mesh's points are single precision, so a point on a shared face may come out a rounding
// error outside both tetrahedra. The first owner wins, so the slack never blends two cells.
constexpr double Slack = 1e-5;
// Blocks of tetrahedra between two progress reports.
constexpr int ProgressBlocks = 20;
constexpr int64_t Nobody = std::numeric_limits<int64_t>::max();

void Corner(const TetMesh& m, uint32_t v, double p[3])
{
  for (int k = 0; k < 3; ++k)
  {
    p[k] = m.Points4[4 * size_t(v) + k];
  }
}

// The lattice in the mesh's shifted coordinates.
Lattice Shifted(const Lattice& l, const double shift[3])
{
  Lattice s = l;
  for (int k = 0; k < 3; ++k)
  {
    s.Origin[k] -= shift[k];
  }
  return s;
}

// The range of lattice indices along axis k whose points lie within [lo, hi] (empty: first > last).
void IndexRange(const Lattice& l, int k, double lo, double hi, int& first, int& last)
{
  const double f = (lo - l.Origin[k]) / l.Spacing[k], g = (hi - l.Origin[k]) / l.Spacing[k];
  first = std::max(0, static_cast<int>(std::ceil(f - Slack)));
  last = std::min(l.Dims[k] - 1, static_cast<int>(std::floor(g + Slack)));
}

void Position(const Lattice& l, int i, int j, int k, double p[3])
{
  const int ijk[3] = { i, j, k };
  for (int a = 0; a < 3; ++a)
  {
    p[a] = l.Origin[a] + ijk[a] * l.Spacing[a];
  }
}

bool Inside(const double l[4])
{
  return l[0] >= -Slack && l[1] >= -Slack && l[2] >= -Slack && l[3] >= -Slack;
}

// Pass 1: every tetrahedron claims the lattice points inside it; the lowest number wins.
struct ClaimPoints
{
  const TetMesh& Mesh;
  const TetCells Cells;
  const Lattice& Grid; // shifted
  std::atomic<int64_t>* Owner;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    for (vtkIdType t = begin; t < end; ++t)
    {
      this->Claim(t);
    }
  }

  void Claim(int64_t t) const
  {
    double p[4][3];
    double lo[3], hi[3];
    for (int v = 0; v < 4; ++v)
    {
      Corner(this->Mesh, this->Cells(size_t(t), v), p[v]);
    }
    int first[3], last[3];
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min({ p[0][k], p[1][k], p[2][k], p[3][k] });
      hi[k] = std::max({ p[0][k], p[1][k], p[2][k], p[3][k] });
      IndexRange(this->Grid, k, lo[k], hi[k], first[k], last[k]);
    }
    for (int z = first[2]; z <= last[2]; ++z)
    {
      for (int y = first[1]; y <= last[1]; ++y)
      {
        for (int x = first[0]; x <= last[0]; ++x)
        {
          double q[3], l[4];
          Position(this->Grid, x, y, z, q);
          if (Barycentric(p[0], p[1], p[2], p[3], q, l) && Inside(l))
          {
            std::atomic<int64_t>& o = this->Owner[this->Grid.Index(x, y, z)];
            int64_t seen = o.load(std::memory_order_relaxed);
            while (t < seen && !o.compare_exchange_weak(seen, t, std::memory_order_relaxed))
            {
            }
          }
        }
      }
    }
  }
};

// Pass 2: each claimed lattice point interpolates its owner's point values (Points4's u and the
// separate opacity), l0 a + l1 b + l2 c + l3 d.
struct Interpolate
{
  const TetMesh& Mesh;
  const TetCells Cells;
  const Lattice& Grid; // shifted
  LatticeSamples& Out;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    const int nx = this->Grid.Dims[0], ny = this->Grid.Dims[1];
    for (vtkIdType i = begin; i < end; ++i)
    {
      const int64_t t = this->Out.Tet[i];
      if (t < 0)
      {
        continue;
      }
      uint32_t v[4];
      this->Cells.Get(size_t(t), v);
      double p[4][3], q[3], l[4];
      for (int a = 0; a < 4; ++a)
      {
        Corner(this->Mesh, v[a], p[a]);
      }
      Position(this->Grid, int(i % nx), int((i / nx) % ny), int(i / (int64_t(nx) * ny)), q);
      Barycentric(p[0], p[1], p[2], p[3], q, l);
      double s = 0, o = 0;
      for (int a = 0; a < 4; ++a)
      {
        const double w = std::clamp(l[a], 0.0, 1.0); // within the slack: the face's value
        s += w * this->Mesh.Points4[4 * size_t(v[a]) + 3];
        o += this->Out.Opacity.empty() ? 0.0 : w * this->Mesh.Opacity[v[a]];
      }
      const double sum = std::clamp(l[0], 0.0, 1.0) + std::clamp(l[1], 0.0, 1.0) +
        std::clamp(l[2], 0.0, 1.0) + std::clamp(l[3], 0.0, 1.0);
      this->Out.Scalar[i] = s / sum;
      if (!this->Out.Opacity.empty())
      {
        this->Out.Opacity[i] = o / sum;
      }
    }
  }
};
} // namespace

bool Barycentric(const double a[3], const double b[3], const double c[3], const double d[3],
  const double p[3], double l[4])
{
  double e1[3], e2[3], e3[3], r[3];
  for (int k = 0; k < 3; ++k)
  {
    e1[k] = b[k] - a[k];
    e2[k] = c[k] - a[k];
    e3[k] = d[k] - a[k];
    r[k] = p[k] - a[k];
  }
  auto det = [](const double* u, const double* v, const double* w)
  {
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
      u[2] * (v[0] * w[1] - v[1] * w[0]);
  };
  const double vol = det(e1, e2, e3);
  const double scale = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]) *
    std::sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]) *
    std::sqrt(e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2]);
  if (!(std::abs(vol) > 1e-12 * scale))
  {
    return false;
  }
  l[1] = det(r, e2, e3) / vol;
  l[2] = det(e1, r, e3) / vol;
  l[3] = det(e1, e2, r) / vol;
  l[0] = 1 - l[1] - l[2] - l[3];
  return true;
}

LatticeSamples SampleOnLattice(
  const TetMesh& mesh, const Lattice& lattice, const std::function<void(double)>& progress)
{
  const int64_t n = lattice.NumberOfPoints();
  const Lattice grid = Shifted(lattice, mesh.Shift);
  const TetCells cells = mesh.Cells();
  std::unique_ptr<std::atomic<int64_t>[]> owner(new std::atomic<int64_t>[size_t(n)]);
  for (int64_t i = 0; i < n; ++i)
  {
    owner[i].store(Nobody, std::memory_order_relaxed);
  }
  const int64_t tets = static_cast<int64_t>(mesh.NumberOfTets());
  ClaimPoints claim{ mesh, cells, grid, owner.get() };
  for (int b = 0; b < ProgressBlocks; ++b)
  {
    const int64_t begin = tets * b / ProgressBlocks, end = tets * (b + 1) / ProgressBlocks;
    psi::Parallel([&] { vtkSMPTools::For(begin, end, claim); });
    if (progress)
    {
      progress(double(b + 1) / (ProgressBlocks + 1));
    }
  }
  LatticeSamples out;
  out.Tet.resize(size_t(n));
  out.Scalar.assign(size_t(n), 0.0);
  if (!mesh.Opacity.empty())
  {
    out.Opacity.assign(size_t(n), 0.0);
  }
  for (int64_t i = 0; i < n; ++i)
  {
    const int64_t t = owner[i].load(std::memory_order_relaxed);
    out.Tet[i] = t == Nobody ? -1 : t;
  }
  Interpolate interpolate{ mesh, cells, grid, out };
  psi::Parallel([&] { vtkSMPTools::For(0, n, interpolate); });
  if (progress)
  {
    progress(1.0);
  }
  return out;
}

} // namespace psi
