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

TetConnectivityResult ComputeTetNeighbors(
  const uint32_t* tets, size_t numTets, size_t numPoints, std::vector<int32_t>& neighbors)
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
      maxId = std::max(maxId, tets[i]);
    }
    numPoints = static_cast<size_t>(maxId) + 1;
  }
  result.NumberOfPoints = numPoints;
  const size_t numFaces = 4 * numTets;

  // 1. Bucket sizes: faces per smallest point id.
  std::vector<uint32_t> start(numPoints + 1, 0);
  for (size_t t = 0; t < numTets; ++t)
  {
    const uint32_t* v = tets + 4 * t;
    for (int f = 0; f < 4; ++f)
    {
      const uint32_t a = v[FaceVerts[f][0]], b = v[FaceVerts[f][1]], c = v[FaceVerts[f][2]];
      ++start[std::min(a, std::min(b, c)) + 1];
    }
  }
  for (size_t p = 0; p < numPoints; ++p)
  {
    start[p + 1] += start[p];
  }

  // 2. Scatter the faces into their buckets with the (middle, largest) key.
  std::vector<FaceEntry> entries(numFaces);
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t t = 0; t < numTets; ++t)
    {
      const uint32_t* v = tets + 4 * t;
      for (int f = 0; f < 4; ++f)
      {
        uint32_t s[3] = { v[FaceVerts[f][0]], v[FaceVerts[f][1]], v[FaceVerts[f][2]] };
        if (s[0] > s[1])
          std::swap(s[0], s[1]);
        if (s[1] > s[2])
          std::swap(s[1], s[2]);
        if (s[0] > s[1])
          std::swap(s[0], s[1]);
        entries[fill[s[0]]++] = { (static_cast<uint64_t>(s[1]) << 32) | s[2],
          static_cast<uint32_t>(4 * t + f) };
      }
    }
  }

  // 3. Per bucket (in parallel): sort by key and pair equal runs. Every face entry belongs to
  // exactly one bucket, so each neighbour slot is written by one thread only.
  vtkSMPThreadLocal<TetConnectivityResult> local;
  vtkSMPTools::For(0, static_cast<vtkIdType>(numPoints), [&](vtkIdType begin, vtkIdType end) {
    TetConnectivityResult& r = local.Local();
    for (vtkIdType p = begin; p < end; ++p)
    {
      FaceEntry* first = entries.data() + start[p];
      FaceEntry* last = entries.data() + start[p + 1];
      std::sort(first, last, [](const FaceEntry& x, const FaceEntry& y) {
        return x.Key < y.Key || (x.Key == y.Key && x.Face < y.Face);
      });
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
  return result;
}

std::vector<uint8_t> BoundaryFaceFlags(const std::vector<int32_t>& neighbors)
{
  const size_t n = neighbors.size() / 4;
  std::vector<uint8_t> flags(n, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(n), [&](vtkIdType begin, vtkIdType end) {
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
