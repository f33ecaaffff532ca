// PsiGeometryProjector: the geometry-shader projector of Maximo et al. 2010 §3.2. Each
// tetrahedron of the visibility order is one point; the geometry shader classifies its projection
// (Marroquim et al. 2006 §3) and emits its triangles, which the fragment shader integrates. The
// program comes from psi::ComposeShaders, once per feature set (VTK's shader cache keeps it).
// PsiComputeProjector runs the same geometry code in a compute pass instead.
#ifndef PsiGeometryProjector_h
#define PsiGeometryProjector_h

#include <cstddef>
#include <functional>
#include <string>

class PsiVisibilityOrder;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
namespace psi
{
struct ShaderFeatures;
}

class PsiGeometryProjector
{
public:
  /// The program of `f` with `integrator`, made ready (bound) by VTK's shader cache; composed
  /// and compiled when the feature set changed (`built` is then true). Null when it does not
  /// compile (VTK reports the log).
  vtkShaderProgram* ReadyProgram(vtkOpenGLRenderWindow* renWin, const psi::ShaderFeatures& f,
    const char* integrator, bool& built);
  /// Draws every tetrahedron of `order` as a point with `program` (bound, with the mesh's
  /// vertex array), its four point ids streamed by the order, on a target of `targetPixels`.
  void Draw(PsiVisibilityOrder& order, vtkShaderProgram* program, size_t targetPixels,
    const std::function<void(size_t first)>& beforeChunk = {}) const;
  void ReleaseGraphicsResources();

private:
  vtkShaderProgram* Program = nullptr; // owned by VTK's shader cache
  std::string Key;
};

#endif
