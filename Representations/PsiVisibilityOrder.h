// PsiVisibilityOrder: the back-to-front order of the tetrahedra on the GPU, as an index buffer
// of GL_POINTS (one per tetrahedron, Maximo et al. 2010 §3.1). It owns the sort (centroid or
// MPVONC, psi::TetSort) and re-sorts only when the mesh, the view or the sort method changes.
#ifndef PsiVisibilityOrder_h
#define PsiVisibilityOrder_h

#include "PsiTetSort.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

class vtkWindow;

class PsiVisibilityOrder
{
public:
  enum Methods
  {
    CENTROID = 0,
    MPVONC = 1
  };

  PsiVisibilityOrder();
  ~PsiVisibilityOrder();

  /// mcvc: model (shifted) to view matrix, row-major.
  bool NeedsUpdate(int meshVersion, int method, const double mcvc[16], bool parallel) const;
  /// Whether the next Update takes a new mesh (the mesh or the method changed): only then does it
  /// use the face neighbours it is offered.
  bool NeedsMesh(int meshVersion, int method) const
  {
    return !this->Sort || meshVersion != this->MeshVersion || method != this->Method;
  }
  /// Sorts `mesh` for the view and uploads the order. `faceNeighbors` (may be empty) are
  /// offered to the sort when the mesh or the method changed (see psi::TetSort::SetMesh).
  void Update(const psi::TetMesh& mesh, int meshVersion, std::vector<int32_t> faceNeighbors,
    int method, const double mcvc[16], bool parallel);
  /// Draws every tetrahedron as a point in order (the VAO of the tetrahedra bound).
  void Draw() const;
  void ReleaseGraphicsResources(vtkWindow* win);

  /// The order on the GPU: a buffer of uint32 tetrahedron ids, and their number.
  unsigned int GetIndexBuffer() const { return this->IndexBuffer; }
  size_t GetSize() const { return this->Order.size(); }
  size_t GetLastCycles() const { return this->LastCycles; }
  /// The order last uploaded, farthest first (what Draw draws).
  const std::vector<uint32_t>& GetOrder() const { return this->Order; }
  double GetLastSortSeconds() const { return this->LastSortSeconds; }

private:
  PsiVisibilityOrder(const PsiVisibilityOrder&) = delete;
  void operator=(const PsiVisibilityOrder&) = delete;

  std::unique_ptr<psi::TetSort> Sort;
  int Method = -1;
  int MeshVersion = -1;
  std::array<double, 16> View{};
  bool Parallel = false;
  std::vector<uint32_t> Order;
  unsigned int IndexBuffer = 0;
  bool OnGPU = false;
  size_t LastCycles = 0;
  double LastSortSeconds = 0;
};

#endif
