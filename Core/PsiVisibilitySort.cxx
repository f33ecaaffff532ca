#include "PsiVisibilitySort.h"

#include "PsiCellCenterDepthSort.h"
#include "PsiMPVONCSort.h"
#include "PsiParallel.h"
#include "PsiTetConnectivity.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>

namespace psi
{
VisibilitySort::~VisibilitySort() = default;

namespace
{
class CentroidSort : public VisibilitySort
{
public:
  void SetMesh(const TetMesh* mesh, std::vector<int32_t>) override
  {
    this->Centroids = ComputeCentroids(mesh->Points4.data(), mesh->Cells(), mesh->NumberOfTets());
  }
  size_t Sort(const double eye[3], bool parallel, std::vector<uint32_t>& order,
    const std::function<void(size_t)>& emitted, SortDirection direction) override
  {
    SortBackToFront(this->Centroids, eye, parallel, order);
    if (direction == SortDirection::NearestFirst)
    {
      std::reverse(order.begin(), order.end());
    }
    if (emitted)
    {
      emitted(order.size());
    }
    return 0;
  }

private:
  std::vector<float> Centroids;
};

class MPVONC : public VisibilitySort
{
public:
  void SetMesh(const TetMesh* mesh, std::vector<int32_t> faceNeighbors) override
  {
    this->Mesh = mesh;
    this->Neighbors = std::move(faceNeighbors);
    if (!this->Neighbors.empty() && !FaceNeighborsMatch(*mesh, this->Neighbors))
    {
      this->Neighbors.clear();
    }
  }
  size_t Sort(const double eye[3], bool parallel, std::vector<uint32_t>& order,
    const std::function<void(size_t)>& emitted, SortDirection direction) override
  {
    const size_t n = this->Mesh->NumberOfTets();
    if (this->Neighbors.size() != 4 * n)
    {
      Parallel(
        [&] {
          ComputeTetNeighbors(
            this->Mesh->Cells(), n, this->Mesh->NumberOfPoints(), this->Neighbors);
        });
    }
    const MPVONCResult r = SortMPVONC(this->Mesh->Points4.data(), this->Mesh->Cells(), n,
      this->Neighbors.data(), eye, parallel, order, emitted, direction);
    return r.CyclesBroken;
  }

private:
  const TetMesh* Mesh = nullptr;
  std::vector<int32_t> Neighbors;
};

// Whether tetrahedron `other` has a point at the position of point id `p`.
bool HasPointAt(const TetMesh& m, TetCells cells, uint32_t other, uint32_t p)
{
  const float* q = &m.Points4[4 * static_cast<size_t>(p)];
  for (int v = 0; v < 4; ++v)
  {
    const float* r = &m.Points4[4 * static_cast<size_t>(cells(other, v))];
    if (r[0] == q[0] && r[1] == q[1] && r[2] == q[2])
    {
      return true;
    }
  }
  return false;
}

// Whether the four neighbour entries of tetrahedron `t` name tetrahedra that have its faces.
bool NeighborsMatchAt(const TetMesh& m, TetCells cells, const std::vector<int32_t>& nb, uint32_t t)
{
  const size_t n = m.NumberOfTets();
  for (int f = 0; f < 4; ++f)
  {
    const int32_t j = nb[4 * static_cast<size_t>(t) + f];
    if (j < 0)
    {
      continue;
    }
    bool match = static_cast<size_t>(j) < n && static_cast<uint32_t>(j) != t;
    for (int v = 0; v < 4 && match; ++v) // face f is opposite vertex f
    {
      match = v == f || HasPointAt(m, cells, static_cast<uint32_t>(j), cells(t, v));
    }
    if (!match)
    {
      return false;
    }
  }
  return true;
}
} // namespace

bool FaceNeighborsMatch(const TetMesh& m, const std::vector<int32_t>& nb)
{
  const size_t n = m.NumberOfTets();
  if (nb.size() != 4 * n)
  {
    return false;
  }
  const TetCells cells = m.Cells();
  std::atomic<bool> ok(true);
  // on threads even under ParaView's Sequential default (psi::Parallel)
  Parallel(
    [&]
    {
      vtkSMPTools::For(0, static_cast<vtkIdType>(n),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType t = begin; t < end && ok.load(std::memory_order_relaxed); ++t)
          {
            if (!NeighborsMatchAt(m, cells, nb, static_cast<uint32_t>(t)))
            {
              ok = false;
            }
          }
        });
    });
  return ok;
}

std::unique_ptr<VisibilitySort> NewCentroidSort()
{
  return std::unique_ptr<VisibilitySort>(new CentroidSort);
}

std::unique_ptr<VisibilitySort> NewMPVONCSort()
{
  return std::unique_ptr<VisibilitySort>(new MPVONC);
}
} // namespace psi
