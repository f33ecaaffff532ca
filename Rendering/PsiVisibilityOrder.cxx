#include "PsiVisibilityOrder.h"

#include "PsiSettings.h"
#include "PsiStopwatch.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkMatrix4x4.h"

#include <algorithm>
#include <array>
#include <utility>

namespace
{
// The eye in model coordinates, or in parallel projection the view direction (0, 0, -1).
void EyeInModel(const double mcvc[16], bool parallel, double eye[3])
{
  double inv[16];
  vtkMatrix4x4::Invert(mcvc, inv);
  for (int k = 0; k < 3; ++k)
  {
    eye[k] = parallel ? -inv[4 * k + 2] : inv[4 * k + 3] / inv[15];
  }
}
} // namespace

PsiVisibilityOrder::PsiVisibilityOrder() = default;

PsiVisibilityOrder::~PsiVisibilityOrder()
{
  if (this->Worker.joinable())
  {
    this->Worker.join();
  }
}

bool PsiVisibilityOrder::NeedsUpdate(int meshVersion, psi::Sorts method, const double mcvc[16],
  bool parallel, psi::SortDirection direction) const
{
  return !this->OnGPU || meshVersion != this->MeshVersion || method != this->Method ||
    direction != this->Direction || parallel != this->Parallel ||
    !std::equal(mcvc, mcvc + 16, this->View.begin());
}

void PsiVisibilityOrder::Update(const psi::TetMesh& mesh, int meshVersion,
  std::vector<int32_t> faceNeighbors, psi::Sorts method, const double mcvc[16], bool parallel,
  psi::SortDirection direction)
{
  this->Finish();
  if (this->NeedsMesh(meshVersion, method))
  {
    this->Sort = method == psi::Sorts::MPVONC ? psi::NewMPVONCSort() : psi::NewCentroidSort();
    this->Sort->SetMesh(&mesh, std::move(faceNeighbors));
  }
  this->Mesh = &mesh;
  this->Size = mesh.NumberOfTets();
  if (!this->StreamBuffer)
  {
    glGenBuffers(1, &this->StreamBuffer);
    glBindBuffer(GL_ARRAY_BUFFER, this->StreamBuffer);
    glBufferData(
      GL_ARRAY_BUFFER, InFlight * MaxChunkTets * 4 * sizeof(uint32_t), nullptr, GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  }
  this->Final = 0;
  std::array<double, 3> eye;
  EyeInModel(mcvc, parallel, eye.data());
  this->Worker = std::thread(
    [this, eye, parallel, direction]()
    {
      const psi::Stopwatch clock;
      const size_t cycles = this->Sort->Sort(
        eye.data(), parallel, this->Order, [this](size_t n) { this->Emitted(n); }, direction);
      const double seconds = clock.Seconds();
      std::lock_guard<std::mutex> guard(this->Lock);
      this->LastCycles = cycles;
      this->LastSortSeconds = seconds;
    });
  this->Method = method;
  this->Direction = direction;
  this->MeshVersion = meshVersion;
  std::copy(mcvc, mcvc + 16, this->View.begin());
  this->Parallel = parallel;
  this->OnGPU = true;
}

void PsiVisibilityOrder::Emitted(size_t count)
{
  {
    std::lock_guard<std::mutex> guard(this->Lock);
    this->Final = count;
  }
  this->Progress.notify_one();
}

void PsiVisibilityOrder::StreamChunk(size_t first, size_t count, size_t at)
{
  {
    std::unique_lock<std::mutex> guard(this->Lock);
    this->Progress.wait(guard, [&] { return this->Final >= first + count; });
  }
  this->Staging.resize(count * 4);
  const psi::TetCells tets = this->Mesh->Cells();
  for (size_t k = 0; k < count; ++k)
  {
    const uint32_t cell = this->Order[first + k];
    tets.Get(cell, &this->Staging[4 * k]);
    if (this->RecordDrawn)
    {
      this->Drawn.push_back(cell);
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, this->StreamBuffer);
  glBufferSubData(
    GL_ARRAY_BUFFER, at * 4 * sizeof(uint32_t), count * 4 * sizeof(uint32_t), this->Staging.data());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void PsiVisibilityOrder::Finish()
{
  if (this->Worker.joinable())
  {
    this->Worker.join();
  }
}

namespace
{
// Waits until the commands before `fence` have run, and deletes it.
void WaitAndDelete(GLsync fence)
{
  GLenum status = GL_TIMEOUT_EXPIRED;
  while (status == GL_TIMEOUT_EXPIRED)
  {
    status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(1000000000));
  }
  glDeleteSync(fence);
}
} // namespace

void PsiVisibilityOrder::Draw(const std::function<void(size_t, size_t)>& drawChunk,
  size_t targetPixels, const std::function<void(size_t first)>& beforeChunk)
{
  // Streamed in chunks (ChunkTetsFor) through InFlight slots of the stream buffer, so that the
  // GPU holds no copy of the cells and no single draw call is unbounded. Mesa's llvmpipe bins
  // each chunk's triangles, with all their fragment inputs, until its rasterizer threads reach
  // them; its geometry stage outruns them, so binned chunks piled up (1.1 GB more peak memory
  // at 2.56M tetrahedra). A fence after each chunk and a wait for the one InFlight chunks back
  // keep at most InFlight chunks binned without draining the pipeline (more in flight were no
  // faster: docs/decisions.md, "Draw chunks and threads"), and free that chunk's
  // slot for the next. Each fence also ends llvmpipe's scene (see ChunkTetsFor).
  std::array<GLsync, InFlight> fences{};
  const size_t n = this->Size, chunk = ChunkTetsFor(n, targetPixels);
  this->Drawn.clear();
  for (size_t first = 0, i = 0; first < n; first += chunk, ++i)
  {
    if (beforeChunk && first > 0)
    {
      beforeChunk(first);
    }
    GLsync& slot = fences[i % InFlight];
    if (slot)
    {
      WaitAndDelete(slot);
    }
    const size_t count = std::min(chunk, n - first), at = (i % InFlight) * MaxChunkTets;
    this->StreamChunk(first, count, at);
    drawChunk(at, count);
    slot = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  }
  for (GLsync fence : fences)
  {
    if (fence)
    {
      glDeleteSync(fence);
    }
  }
}

void PsiVisibilityOrder::ReleaseGraphicsResources(vtkWindow*)
{
  if (this->Worker.joinable())
  {
    this->Worker.join(); // the order is dropped with the buffer
  }
  if (this->StreamBuffer)
  {
    glDeleteBuffers(1, &this->StreamBuffer);
  }
  this->StreamBuffer = 0;
  this->OnGPU = false;
}
