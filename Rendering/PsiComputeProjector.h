// PsiComputeProjector: the compute-shader projector. A compute pass classifies and projects a
// chunk of the visibility order (Shaders/PsiProjectCS.glsl, the geometry shader's own code) into
// a vertex buffer and an index buffer, which the draw program (a pass-through vertex shader and
// the usual fragment shader) then draws in order; chunk after chunk, the buffers are reused.
// Programs come from psi::ComposeComputeProjector, once per feature set.
#ifndef PsiComputeProjector_h
#define PsiComputeProjector_h

#include "PsiVolumeRenderingModule.h"
#include "vtkSmartPointer.h"

#include <cstddef>
#include <functional>
#include <map>
#include <string>

class PsiVisibilityOrder;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;
namespace psi
{
struct ShaderFeatures;
}

class PSIVOLUMERENDERING_EXPORT PsiComputeProjector
{
public:
  PsiComputeProjector();
  ~PsiComputeProjector();

  /// Whether the context can run the projector (OpenGL 4.3: compute shaders, storage buffers).
  static bool IsSupported(vtkOpenGLRenderWindow* renWin);
  /// Whether this frame projects with compute shaders, when the settings ask for them
  /// (psi::UsesComputeProjector): asked for where OpenGL 4.3 is missing gives false, with a
  /// warning.
  static bool Chosen(bool asked, vtkOpenGLRenderWindow* renWin);
  /// Composes and builds the programs for `f` (once per feature key: `built` tells) and leaves
  /// the compute program bound. Null, with `error` set, when a program does not build.
  vtkShaderProgram* ReadyComputeProgram(
    const psi::ShaderFeatures& f, const char* integrator, std::string& error, bool& built);
  /// The draw program of the last ReadyComputeProgram, made ready (bound) by VTK's shader cache.
  vtkShaderProgram* ReadyDrawProgram(vtkOpenGLRenderWindow* renWin);
  /// Projects and draws the tetrahedra of `order`, chunk by chunk as it streams their point ids
  /// (PsiVisibilityOrder::Draw), in passes that fit the buffers. Both programs'
  /// uniforms must be set. Leaves no program bound (VTK's shader cache is told).
  /// Each pass's buffers fit `maxBlockBytes` (GL_MAX_SHADER_STORAGE_BLOCK_SIZE, PsiDriverLimits).
  /// False, with `error` set, when not even one work group's triangles fit it (nothing drawn).
  /// `beforeChunk` as for PsiVisibilityOrder::Draw (the vertex array is
  /// bound again after it).
  bool Draw(vtkOpenGLRenderWindow* renWin, PsiVisibilityOrder& order, size_t targetPixels,
    long long maxBlockBytes, std::string& error,
    const std::function<void(size_t first)>& beforeChunk = {});
  void ReleaseGraphicsResources(vtkWindow* win);

  /// Bytes of the reused vertex and index buffers (their size bounds the tetrahedra per pass).
  static constexpr size_t BufferBudget = size_t(48) << 20;

private:
  PsiComputeProjector(const PsiComputeProjector&) = delete;
  void operator=(const PsiComputeProjector&) = delete;
  void ReserveBuffers(size_t tetsPerPass);

  vtkShaderProgram* Compute = nullptr;                            // the last ready, one of Built
  std::map<std::string, vtkSmartPointer<vtkShaderProgram>> Built; // by compute shader source
  vtkShaderProgram* DrawProgram = nullptr;                        // owned by VTK's shader cache
  std::string DrawVertex, DrawFragment;
  std::string Key;
  int SlotVertices = 0, SlotTriangles = 0, Vec4sPerVertex = 0;
  unsigned int Vertices = 0; // buffer: the projected vertices of one pass (vertex attributes)
  unsigned int Indices = 0;  // buffer: the triangles' indices of one pass
  unsigned int VAO = 0;
  size_t ReservedVec4s = 0, ReservedIndices = 0; // the buffers' sizes
};

#endif
