// PsiOpacityMasks: early ray termination of a front-to-back image, in one piece. While the
// tetrahedra are composited nearest first ("under", Moreland's dissertation §2.2, Eq. 2.13) into
// the render target's float image, a mask after every stride of the visibility order writes
// depth 0 where the image drawn so far has reached psi::SaturatedOpacity (PsiOpaqueMaskFS.glsl),
// so that the fragments still to come there fail the depth test before they are shaded. It owns
// when to mask (a stride of whole chunks, psi::DrawWay::MasksPerFrame a frame at first, doubled
// after a mask that found no opaque pixel), the mask pass, and the count of the pixels each mask
// found opaque (GL_SAMPLES_PASSED, read when the next mask is due: docs/decisions.md "Early ray
// termination: how it is built" has the figures). The draw loop asks it before each chunk
// (PsiVisibilityOrder::Draw); nothing re-enters the render target.
#ifndef PsiOpacityMasks_h
#define PsiOpacityMasks_h

#include "PsiSamplesPassed.h"

#include <algorithm>
#include <cstddef>
#include <memory>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class PsiOpacityMasks
{
public:
  PsiOpacityMasks();
  ~PsiOpacityMasks();

  /// Whether this OpenGL has what a mask needs (glTextureBarrier: OpenGL 4.5 or
  /// ARB_texture_barrier): the plan draws front to back only then.
  static bool IsSupported();
  /// Starts an image of `tets` tetrahedra drawn in chunks of `chunk` into `image` (the render
  /// target's color attachment, bound for drawing with the depth test on), with `masksPerFrame`
  /// masks a frame at first.
  void Begin(vtkTextureObject* image, size_t tets, size_t chunk, int masksPerFrame);
  /// Whether a mask is due before the chunk that starts at tetrahedron `first`.
  bool IsDue(size_t first) const { return this->Image && first >= this->Next; }
  /// The mask before the chunk at `first`; then `drawProgram` (if any) and the vertex array bound
  /// again. The stride to the next one doubles when the previous mask found no opaque pixel.
  void Mask(size_t first, vtkOpenGLRenderWindow* renWin, vtkShaderProgram* drawProgram);
  /// Ends the image: the last mask's count taken (its query free for the next image).
  void End();
  void ReleaseGraphicsResources(vtkWindow* win);

  /// Tetrahedra between two masks at first: whole chunks, at most `masksPerFrame` a frame.
  static constexpr size_t StrideTets(size_t tets, size_t chunk, int masksPerFrame)
  {
    const size_t strides = static_cast<size_t>(std::max(1, masksPerFrame));
    return std::max(chunk, (tets / strides + chunk - 1) / chunk * chunk);
  }

private:
  PsiOpacityMasks(const PsiOpacityMasks&) = delete;
  void operator=(const PsiOpacityMasks&) = delete;
  bool PreviousFoundOpaque();

  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  PsiSamplesPassed Samples;          ///< the pixels the last mask found opaque
  vtkTextureObject* Image = nullptr; ///< the image being drawn (null: no image begun)
  size_t Stride = 0, Next = 0;       ///< tetrahedra between masks; where the next one is due
};

#endif
