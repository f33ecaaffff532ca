// PsiVisibilityOrder: the visibility order of the tetrahedra (farthest first, or nearest first
// for front-to-back compositing), streamed to the GPU as GL_POINTS
// (one per tetrahedron carrying its four point ids, Maximo et al. 2010 §3.1). It owns the sort
// (centroid or MPVONC, psi::VisibilitySort) and re-sorts only when the mesh, the view or the sort
// method changes.
//
// The sort runs on a worker thread while the frame draws. MPVONC emits the order from its
// start (the farthest or the nearest tetrahedra), so Draw uploads and draws each chunk as soon
// as the sort has finished it: the rasterizer starts on the first chunks instead of waiting for
// the whole sort, in which llvmpipe's threads would have nothing to draw (docs/decisions.md,
// "Visibility order").
#ifndef PsiVisibilityOrder_h
#define PsiVisibilityOrder_h

#include "PsiMeasuredChoice.h" // psi::DefaultMasksPerFrame
#include "PsiSettings.h"       // psi::Sorts
#include "PsiSortDirection.h"
#include "PsiVisibilitySort.h"

#include <algorithm>
#include <array>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

class vtkWindow;

class PsiVisibilityOrder
{
public:
  PsiVisibilityOrder();
  ~PsiVisibilityOrder();

  /// mcvc: model (shifted) to view matrix, row-major.
  bool NeedsUpdate(int meshVersion, psi::Sorts method, const double mcvc[16], bool parallel,
    psi::SortDirection direction) const;
  /// Whether the next Update takes a new mesh (the mesh or the method changed): only then does it
  /// use the face neighbours it is offered.
  bool NeedsMesh(int meshVersion, psi::Sorts method) const
  {
    return !this->Sort || meshVersion != this->MeshVersion || method != this->Method;
  }
  /// Starts sorting `mesh` for the view (on the worker thread); `mesh` must stay unchanged while
  /// this order draws it. `faceNeighbors` (may be empty) are offered to the sort when the mesh
  /// or the method changed (see psi::VisibilitySort::SetMesh).
  void Update(const psi::TetMesh& mesh, int meshVersion, std::vector<int32_t> faceNeighbors,
    psi::Sorts method, const double mcvc[16], bool parallel, psi::SortDirection direction);
  /// Streams the tetrahedra in order, chunk by chunk, each as soon as the sort has finished it:
  /// writes the chunk's four point ids per tetrahedron to the stream buffer (GetStreamBuffer)
  /// and calls drawChunk(first, count), `first` being the chunk's first tetrahedron there.
  /// Chunks are ChunkTetsFor(GetSize(), targetPixels) tetrahedra. `beforeChunk`, when set, is
  /// called with each chunk's first tetrahedron before it is streamed but the first's (front to
  /// back, PsiOpacityMasks masks the opaque pixels there).
  void Draw(const std::function<void(size_t first, size_t count)>& drawChunk, size_t targetPixels,
    const std::function<void(size_t first)>& beforeChunk = {});
  /// Waits for the sort (before GetOrder, GetLastCycles and GetLastSortSeconds are read).
  void Finish();
  void ReleaseGraphicsResources(vtkWindow* win);

  /// The buffer Draw streams the ordered tetrahedra through: InFlight chunks of at most
  /// MaxChunkTets uvec4 point ids (the GPU keeps no copy of the mesh's cells).
  unsigned int GetStreamBuffer() const { return this->StreamBuffer; }
  static constexpr size_t MaxChunkTets = size_t(1) << 15;
  static constexpr size_t InFlight = 2;
  /// Tetrahedra per draw chunk for `tets` tetrahedra on a target of `pixels` pixels. Each chunk
  /// ends one of llvmpipe's scenes, whose binned triangles its rasterizer threads read back.
  /// Where cells are small (more than SmallCellsPerPixel tetrahedra per pixel) a triangle covers
  /// a few pixels, and reading its binned data (about 450 bytes with the ray terms) costs more
  /// than shading it: chunks of 4,096 keep a scene within the rasterizer's cache. Where cells
  /// are larger, each scene's end costs more than that saves, and chunks stay at 32,768
  /// (docs/decisions.md, "Draw chunks and threads", has the figures).
  static constexpr size_t ChunkTetsFor(size_t tets, size_t pixels)
  {
    return tets > SmallCellsPerPixel * pixels ? size_t(1) << 12 : MaxChunkTets;
  }
  static constexpr size_t SmallCellsPerPixel = 4;
  /// Tetrahedra in the order.
  size_t GetSize() const { return this->Size; }
  size_t GetLastCycles() const { return this->LastCycles; }
  /// Testing aid, off by default: keep the tetrahedra in the order the last Draw streamed them
  /// to the GPU (GetDrawn).
  void SetRecordDrawn(bool on) { this->RecordDrawn = on; }
  const std::vector<uint32_t>& GetDrawn() const { return this->Drawn; }
  double GetLastSortSeconds() const { return this->LastSortSeconds; }

private:
  PsiVisibilityOrder(const PsiVisibilityOrder&) = delete;
  void operator=(const PsiVisibilityOrder&) = delete;

  /// Writes the point ids of Order[first, first + count) to the stream buffer at tetrahedron
  /// `at`, once the sort has emitted them.
  void StreamChunk(size_t first, size_t count, size_t at);
  /// The sort's report from its thread: entries of Order that are final.
  void Emitted(size_t count);

  std::unique_ptr<psi::VisibilitySort> Sort;
  std::thread Worker;
  std::mutex Lock;
  std::condition_variable Progress;
  size_t Final = 0; ///< entries of Order the sort has emitted (guarded by Lock)
  psi::Sorts Method = psi::Sorts::MPVONC; ///< the sort's, once there is one
  psi::SortDirection Direction = psi::SortDirection::FarthestFirst;
  int MeshVersion = -1;
  std::array<double, 16> View{};
  bool Parallel = false;
  std::vector<uint32_t> Order;
  size_t Size = 0; ///< tetrahedra in the order being drawn
  const psi::TetMesh* Mesh = nullptr;
  std::vector<uint32_t> Staging; ///< one chunk's point ids on their way to StreamBuffer
  bool RecordDrawn = false;
  std::vector<uint32_t> Drawn;
  unsigned int StreamBuffer = 0;
  bool OnGPU = false;
  size_t LastCycles = 0;
  double LastSortSeconds = 0;
};

#endif
