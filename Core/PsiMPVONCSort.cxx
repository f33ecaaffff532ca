#include "PsiMPVONCSort.h"

#include "PsiParallel.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <queue>

namespace psi
{
namespace
{
// Face i of a tetrahedron is opposite its vertex i (same convention as PsiTetConnectivity).
constexpr int FaceVerts[4][3] = { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 2 } };

// Relation across face f of tetrahedron t, stored on both sides of the face.
constexpr int8_t NoOrder = 0;
constexpr int8_t NeighborInFront = 1; // t is behind the face: t comes first
constexpr int8_t NeighborBehind = -1; // the neighbour is behind the face: it comes first

// A tetrahedron's four relations packed in one byte, two bits per face (1 KB per 1,000 cells
// instead of 4 KB: the sort's working set).
uint8_t PackRelation(int8_t r, int f)
{
  return static_cast<uint8_t>((r == NeighborInFront ? 1 : r == NeighborBehind ? 2 : 0) << (2 * f));
}

int8_t RelationAt(uint8_t packed, int f)
{
  const int code = (packed >> (2 * f)) & 3;
  return code == 1 ? NeighborInFront : code == 2 ? NeighborBehind : NoOrder;
}

// Same ordered-bits key as psi::SortBackToFront: ascending key = farthest first (or nearest
// first), ties by id.
uint64_t DepthKey(float d, uint32_t id, SortDirection direction)
{
  uint32_t u;
  std::memcpy(&u, &d, sizeof(u));
  u = (u & 0x80000000u) ? ~u : (u | 0x80000000u);
  return (static_cast<uint64_t>(direction == SortDirection::FarthestFirst ? ~u : u) << 32) | id;
}

struct Counts
{
  size_t Constraints = 0, Degenerate = 0, Inconsistent = 0;
};
// The fallback's sort key of tetrahedron t: distance from the eye to its centroid, or depth
// along the view direction (as in SortBackToFront).
uint64_t CentroidKey(const float* points4, const uint32_t* v, uint32_t t, const double eye[3],
  bool parallel, SortDirection direction)
{
  float ctr[3] = { 0, 0, 0 };
  for (int k = 0; k < 4; ++k)
  {
    for (int a = 0; a < 3; ++a)
    {
      ctr[a] += 0.25f * points4[4 * static_cast<size_t>(v[k]) + a];
    }
  }
  if (parallel)
  {
    return DepthKey(
      static_cast<float>(ctr[0] * eye[0] + ctr[1] * eye[1] + ctr[2] * eye[2]), t, direction);
  }
  const float dx = ctr[0] - static_cast<float>(eye[0]);
  const float dy = ctr[1] - static_cast<float>(eye[1]);
  const float dz = ctr[2] - static_cast<float>(eye[2]);
  return DepthKey(dx * dx + dy * dy + dz * dz, t, direction);
}

// Williams §4: the relation across face f of the tetrahedron with points v. The eye is compared
// with the face plane: when the eye and the opposite vertex are on the same side, the neighbour
// is behind the face. NoOrder for an edge-on face (the eye in its plane) or a flat tetrahedron.
int8_t FaceRelation(
  const float* points4, const uint32_t* v, int f, const double eye[3], bool parallel)
{
  auto P = [&](uint32_t id) { return points4 + 4 * static_cast<size_t>(id); };
  const float* a = P(v[FaceVerts[f][0]]);
  const float* b = P(v[FaceVerts[f][1]]);
  const float* cc = P(v[FaceVerts[f][2]]);
  const float* o = P(v[f]);
  const double u[3] = { double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2] };
  const double w[3] = { double(cc[0]) - a[0], double(cc[1]) - a[1], double(cc[2]) - a[2] };
  const double N[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
    u[0] * w[1] - u[1] * w[0] };
  const double so =
    N[0] * (double(o[0]) - a[0]) + N[1] * (double(o[1]) - a[1]) + N[2] * (double(o[2]) - a[2]);
  double e[3]; // toward the eye; in parallel projection the eye is at infinity
  for (int k = 0; k < 3; ++k)
  {
    e[k] = parallel ? -eye[k] : eye[k] - a[k];
  }
  const double se = N[0] * e[0] + N[1] * e[1] + N[2] * e[2];
  const double scale = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]) *
    std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  if (so == 0 || !(std::abs(se) > 1e-10 * scale))
  {
    return NoOrder;
  }
  return (so > 0) == (se > 0) ? NeighborBehind : NeighborInFront;
}

// Face j of tetrahedron nb that it shares with t, or 4 when nb does not list t (a one-sided
// entry: no constraint).
int SharedFace(const int32_t* neighbors, int64_t nb, int64_t t)
{
  int j = 0;
  while (j < 4 && neighbors[4 * nb + j] != t)
  {
    ++j;
  }
  return j;
}

// Phase I (Williams §4, "the behind relation"). Each interior face is decided once, by the
// tetrahedron with the smaller id (first pass), and the other side takes the opposite (second
// pass), so the two sides always agree: that consistency makes the sort end in a permutation
// whatever the floating-point signs. Each pass writes only its own tetrahedron's byte, the
// second reading the first's.
void BehindRelation(const float* points4, TetCells tets, int64_t n, const int32_t* neighbors,
  const double eye[3], bool parallel, std::vector<uint8_t>& rel, MPVONCResult& result)
{
  std::vector<uint8_t> decided(static_cast<size_t>(n), 0);
  vtkSMPThreadLocal<Counts> localCounts;
  vtkSMPTools::For(0, static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    {
      Counts& c = localCounts.Local();
      for (vtkIdType t = begin; t < end; ++t)
      {
        uint32_t v[4];
        tets.Get(static_cast<size_t>(t), v);
        for (int f = 0; f < 4; ++f)
        {
          const int64_t nb = neighbors[4 * t + f];
          if (nb <= t || nb >= n)
          {
            continue; // boundary, or decided by the neighbour
          }
          if (SharedFace(neighbors, nb, t) == 4)
          {
            ++c.Inconsistent;
            continue;
          }
          const int8_t r = FaceRelation(points4, v, f, eye, parallel);
          if (r == NoOrder)
          {
            ++c.Degenerate;
            continue;
          }
          ++c.Constraints;
          decided[t] |= PackRelation(r, f);
        }
      }
    });
  rel.resize(static_cast<size_t>(n));
  vtkSMPTools::For(0, static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    {
      Counts& c = localCounts.Local();
      for (vtkIdType t = begin; t < end; ++t)
      {
        uint8_t packed = decided[t];
        for (int f = 0; f < 4; ++f)
        {
          const int64_t nb = neighbors[4 * t + f];
          if (nb < 0 || nb >= t)
          {
            continue; // boundary, itself, or decided above
          }
          const int j = SharedFace(neighbors, nb, t);
          if (j == 4)
          {
            ++c.Inconsistent;
            continue;
          }
          packed |= PackRelation(static_cast<int8_t>(-RelationAt(decided[nb], j)), f);
        }
        rel[t] = packed;
      }
    });
  for (const Counts& c : localCounts)
  {
    result.Constraints += c.Constraints;
    result.DegenerateFaces += c.Degenerate;
    result.InconsistentFaces += c.Inconsistent;
  }
}

// The relation of a neighbour that must be emitted before the tetrahedron: the one behind it
// (farthest first), or the one in front of it (nearest first: the same DAG, edges reversed).
int8_t EmittedBefore(SortDirection direction)
{
  return direction == SortDirection::FarthestFirst ? NeighborBehind : NeighborInFront;
}

// Phase II (Williams §5): in-degree = number of neighbours behind the tetrahedron (in front of
// it, nearest first). The sources (in-degree 0) are the cells whose faces pointing away from the
// viewer are all boundary faces (or edge-on): in a convex mesh, the cells on the far side of the
// boundary (nearest first: on the near side).
std::vector<uint8_t> InDegrees(const std::vector<uint8_t>& rel, int64_t n, SortDirection direction)
{
  const int8_t before = EmittedBefore(direction);
  std::vector<uint8_t> indeg(static_cast<size_t>(n), 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const int8_t r[4] = { RelationAt(rel[t], 0), RelationAt(rel[t], 1), RelationAt(rel[t], 2),
          RelationAt(rel[t], 3) };
        // (Written with std::count: GCC 12 -O3 miscompiled a uint8_t "k += cond ? 1 : 0" loop
        // here, adding the vector mask -1 instead of 1.)
        indeg[t] = static_cast<uint8_t>(std::count(r, r + 4, before));
      }
    });
  return indeg;
}

// Phase III (Williams §5, with MPVONC's depth heuristic of §6): Kahn's topological sort in which
// the ready tetrahedron taken next is always the farthest one (min-heap on the key, computed when
// the tetrahedron becomes ready); when none is ready (a cycle, Williams §7) the farthest
// remaining one is taken. Nearest first: the nearest, in the reversed DAG.
template <class Key>
void TopologicalOrder(const Key& key, const int32_t* neighbors, const std::vector<uint8_t>& rel,
  std::vector<uint8_t>& indeg, std::vector<uint32_t>& order,
  const std::function<void(size_t)>& emittedSoFar, SortDirection direction, MPVONCResult& result)
{
  const int8_t after = static_cast<int8_t>(-EmittedBefore(direction));
  const size_t numTets = indeg.size();
  std::vector<uint64_t> heap;
  heap.reserve(1024);
  for (size_t t = 0; t < numTets; ++t)
  {
    if (indeg[t] == 0)
    {
      heap.push_back(key(static_cast<uint32_t>(t)));
    }
  }
  result.Sources = heap.size();
  std::priority_queue<uint64_t, std::vector<uint64_t>, std::greater<uint64_t>> ready(
    std::greater<uint64_t>(), std::move(heap));
  std::vector<uint8_t> emitted(numTets, 0);
  std::vector<uint64_t> allByDepth; // built on the first cycle only
  size_t fallback = 0;
  order.resize(numTets);
  size_t k = 0; // tetrahedra emitted
  while (k < numTets)
  {
    uint32_t t;
    if (!ready.empty())
    {
      t = static_cast<uint32_t>(ready.top() & 0xffffffffu);
      ready.pop();
      if (emitted[t])
      {
        continue; // re-queued after a cycle break had already emitted it
      }
    }
    else
    {
      if (allByDepth.empty())
      {
        allByDepth.resize(numTets);
        for (size_t i = 0; i < numTets; ++i)
        {
          allByDepth[i] = key(static_cast<uint32_t>(i));
        }
        vtkSMPTools::Sort(allByDepth.begin(), allByDepth.end());
      }
      while (emitted[allByDepth[fallback] & 0xffffffffu])
      {
        ++fallback;
      }
      t = static_cast<uint32_t>(allByDepth[fallback] & 0xffffffffu);
      ++result.CyclesBroken;
      result.ViolatedConstraints += indeg[t];
    }
    emitted[t] = 1;
    order[k++] = t;
    if (emittedSoFar && k % EmittedStep == 0)
    {
      emittedSoFar(k);
    }
    for (int f = 0; f < 4; ++f)
    {
      if (RelationAt(rel[t], f) == after)
      {
        const uint32_t nb = static_cast<uint32_t>(neighbors[4 * static_cast<size_t>(t) + f]);
        if (indeg[nb] > 0 && --indeg[nb] == 0 && !emitted[nb])
        {
          ready.push(key(nb));
        }
      }
    }
  }
}
} // namespace

MPVONCResult SortMPVONC(const float* points4, TetCells tets, size_t numTets,
  const int32_t* neighbors, const double eye[3], bool parallel, std::vector<uint32_t>& order,
  const std::function<void(size_t)>& emitted, SortDirection direction)
{
  MPVONCResult result;
  order.clear();
  if (numTets == 0)
  {
    if (emitted)
    {
      emitted(0);
    }
    return result;
  }
  const int64_t n = static_cast<int64_t>(numTets);
  std::vector<uint8_t> rel, indeg;
  // Phases I and II on all cores: nothing is emitted, so nothing is drawn, until they end.
  Parallel(
    [&]
    {
      BehindRelation(points4, tets, n, neighbors, eye, parallel, rel, result);
      indeg = InDegrees(rel, n, direction);
    });
  const auto key = [&](uint32_t t)
  {
    uint32_t v[4];
    tets.Get(t, v);
    return CentroidKey(points4, v, t, eye, parallel, direction);
  };
  TopologicalOrder(key, neighbors, rel, indeg, order, emitted, direction, result);
  if (emitted)
  {
    emitted(numTets);
  }
  return result;
}

} // namespace psi
