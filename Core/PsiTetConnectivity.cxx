#include "PsiTetConnectivity.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <utility>

namespace psi
{
namespace
{
// The face of a tetrahedron opposite vertex i is made of the three others.
constexpr int FaceVerts[4][3] = { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 2 } };

struct FaceEntry
{
  uint64_t Key;  // (middle id << 32) | largest id: the face within its smallest-id bucket
  uint32_t Face; // 4 * tet + local face
};
} // namespace

namespace
{
// The three point ids of face f of tetrahedron v, ascending.
void SortedFace(const uint32_t* v, int f, uint32_t s[3])
{
  s[0] = v[FaceVerts[f][0]];
  s[1] = v[FaceVerts[f][1]];
  s[2] = v[FaceVerts[f][2]];
  if (s[0] > s[1])
    std::swap(s[0], s[1]);
  if (s[1] > s[2])
    std::swap(s[1], s[2]);
  if (s[0] > s[1])
    std::swap(s[0], s[1]);
}

// Calls visit(t, f, s) for face f of every tetrahedron t, s its point ids ascending.
template <typename Visit>
void ForEachSortedFace(TetCells tets, size_t numTets, Visit&& visit)
{
  for (size_t t = 0; t < numTets; ++t)
  {
    uint32_t v[4];
    tets.Get(t, v);
    for (int f = 0; f < 4; ++f)
    {
      uint32_t s[3];
      SortedFace(v, f, s);
      visit(t, f, s);
    }
  }
}

// Pairs the faces whose smallest point id is in [lo, hi): scatters them into their buckets
// (`start`: bucket offsets by smallest id) with the (middle, largest) key, then per bucket (in
// parallel) sorts by key and pairs equal runs. Every face belongs to exactly one bucket, so each
// neighbour slot is written by one thread only.
void PairFaces(TetCells tets, size_t numTets, const std::vector<uint32_t>& start, size_t lo,
  size_t hi, std::vector<FaceEntry>& entries, std::vector<int32_t>& neighbors,
  TetConnectivityResult& result)
{
  const uint32_t base = start[lo];
  entries.resize(start[hi] - base);
  std::vector<uint32_t> fill(start.begin() + lo, start.begin() + hi);
  ForEachSortedFace(tets, numTets,
    [&](size_t t, int f, const uint32_t* s)
    {
      if (s[0] >= lo && s[0] < hi)
      {
        entries[fill[s[0] - lo]++ - base] = { (static_cast<uint64_t>(s[1]) << 32) | s[2],
          static_cast<uint32_t>(4 * t + f) };
      }
    });
  vtkSMPThreadLocal<TetConnectivityResult> local;
  vtkSMPTools::For(static_cast<vtkIdType>(lo), static_cast<vtkIdType>(hi),
    [&](vtkIdType begin, vtkIdType end)
    {
      TetConnectivityResult& r = local.Local();
      for (vtkIdType p = begin; p < end; ++p)
      {
        FaceEntry* first = entries.data() + (start[p] - base);
        FaceEntry* last = entries.data() + (start[p + 1] - base);
        std::sort(first, last,
          [](const FaceEntry& x, const FaceEntry& y)
          { return x.Key < y.Key || (x.Key == y.Key && x.Face < y.Face); });
        for (FaceEntry* run = first; run != last;)
        {
          FaceEntry* runEnd = run + 1;
          while (runEnd != last && runEnd->Key == run->Key)
          {
            ++runEnd;
          }
          const ptrdiff_t count = runEnd - run;
          if (count == 1)
          {
            ++r.BoundaryFaces;
          }
          else if (count == 2)
          {
            ++r.InteriorFaces;
            neighbors[run[0].Face] = static_cast<int32_t>(run[1].Face / 4);
            neighbors[run[1].Face] = static_cast<int32_t>(run[0].Face / 4);
          }
          else
          {
            ++r.NonManifoldFaces; // left at -1 on every side, see the header
          }
          run = runEnd;
        }
      }
    });
  for (const TetConnectivityResult& r : local)
  {
    result.InteriorFaces += r.InteriorFaces;
    result.BoundaryFaces += r.BoundaryFaces;
    result.NonManifoldFaces += r.NonManifoldFaces;
  }
}
} // namespace

TetConnectivityResult ComputeTetNeighbors(TetCells tets, size_t numTets, size_t numPoints,
  std::vector<int32_t>& neighbors, size_t facesPerPass)
{
  TetConnectivityResult result;
  neighbors.assign(4 * numTets, -1);
  if (numTets == 0)
  {
    return result;
  }
  if (numPoints == 0)
  {
    uint32_t maxId = 0;
    for (size_t i = 0; i < 4 * numTets; ++i)
    {
      maxId = std::max(maxId, tets(i / 4, static_cast<int>(i % 4)));
    }
    numPoints = static_cast<size_t>(maxId) + 1;
  }
  result.NumberOfPoints = numPoints;
  const size_t numFaces = 4 * numTets;

  // Bucket offsets: faces per smallest point id.
  std::vector<uint32_t> start(numPoints + 1, 0);
  ForEachSortedFace(tets, numTets, [&](size_t, int, const uint32_t* s) { ++start[s[0] + 1]; });
  for (size_t p = 0; p < numPoints; ++p)
  {
    start[p + 1] += start[p];
  }
  // The buckets in passes of at most `budget` faces (at least one bucket each): a table of all
  // faces would take 16 bytes per face, 164 MB at 2.56M tetrahedra, on top of the mesh.
  const size_t budget =
    facesPerPass > 0 ? facesPerPass : std::max<size_t>(numFaces / 8, size_t(1) << 20);
  std::vector<FaceEntry> entries;
  for (size_t lo = 0; lo < numPoints;)
  {
    size_t hi = lo + 1;
    while (hi < numPoints && start[hi + 1] - start[lo] <= budget)
    {
      ++hi;
    }
    PairFaces(tets, numTets, start, lo, hi, entries, neighbors, result);
    lo = hi;
  }
  return result;
}

std::vector<uint8_t> BoundaryFaceFlags(const std::vector<int32_t>& neighbors)
{
  const size_t n = neighbors.size() / 4;
  std::vector<uint8_t> flags(n, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        uint8_t b = 0;
        for (int f = 0; f < 4; ++f)
        {
          b |= neighbors[4 * t + f] < 0 ? static_cast<uint8_t>(1u << f) : 0;
        }
        flags[t] = b;
      }
    });
  return flags;
}

} // namespace psi
