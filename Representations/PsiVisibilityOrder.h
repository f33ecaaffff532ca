// PsiVisibilityOrder: the back-to-front order of the tetrahedra on the GPU, as an index buffer
// of GL_POINTS (one per tetrahedron, Maximo et al. 2010 §3.1). It owns the sort (centroid or
// MPVONC, psi::TetSort) and re-sorts only when the mesh, the view or the sort method changes.
//
// The sort runs on a worker thread while the frame draws. MPVONC emits the farthest
// tetrahedra first, so Draw uploads and draws each chunk as soon as the sort has finished it:
// the rasterizer starts on the far chunks instead of waiting for the whole sort (at 2.56M
// tetrahedra, 0.37 s in which llvmpipe's threads had nothing to draw).
#ifndef PsiVisibilityOrder_h
#define PsiVisibilityOrder_h

#include "PsiTetSort.h"

#include <array>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
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
  /// Starts sorting `mesh` for the view (on the worker thread); `mesh` must stay unchanged until
  /// Finish. `faceNeighbors` (may be empty) are offered to the sort when the mesh or the method
  /// changed (see psi::TetSort::SetMesh).
  void Update(const psi::TetMesh& mesh, int meshVersion, std::vector<int32_t> faceNeighbors,
    int method, const double mcvc[16], bool parallel);
  /// Draws every tetrahedron as a point in order (the VAO of the tetrahedra bound), each chunk
  /// as soon as the sort has finished it.
  void Draw();
  /// Waits for the sort and uploads the whole order (before the index buffer is used otherwise,
  /// and before GetOrder, GetLastCycles and GetLastSortSeconds are read).
  void Finish();
  void ReleaseGraphicsResources(vtkWindow* win);

  /// The order on the GPU: a buffer of uint32 tetrahedron ids, and their number.
  unsigned int GetIndexBuffer() const { return this->IndexBuffer; }
  size_t GetSize() const { return this->Size; }
  size_t GetLastCycles() const { return this->LastCycles; }
  /// The order last uploaded, farthest first (what Draw draws).
  const std::vector<uint32_t>& GetOrder() const { return this->Order; }
  double GetLastSortSeconds() const { return this->LastSortSeconds; }

private:
  PsiVisibilityOrder(const PsiVisibilityOrder&) = delete;
  void operator=(const PsiVisibilityOrder&) = delete;

  /// Uploads the order up to entry `end`, once the sort has emitted it.
  void UploadThrough(size_t end);
  /// The sort's report from its thread: entries of Order that are final.
  void Emitted(size_t count);

  std::unique_ptr<psi::TetSort> Sort;
  std::thread Worker;
  std::mutex Lock;
  std::condition_variable Progress;
  size_t Final = 0;    ///< entries of Order the sort has emitted (guarded by Lock)
  size_t Uploaded = 0; ///< entries of Order in IndexBuffer
  int Method = -1;
  int MeshVersion = -1;
  std::array<double, 16> View{};
  bool Parallel = false;
  std::vector<uint32_t> Order;
  size_t Size = 0; ///< tetrahedra in the order being drawn
  unsigned int IndexBuffer = 0;
  bool OnGPU = false;
  size_t LastCycles = 0;
  double LastSortSeconds = 0;
};

#endif
