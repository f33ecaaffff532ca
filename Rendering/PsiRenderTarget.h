// PsiRenderTarget: where the volume is drawn and how it reaches the scene. The tetrahedra are
// composited back to front ("over", premultiplied) into a float color target whose depth
// attachment is a copy of the scene's depth, so that the hardware depth test hides cells behind
// opaque geometry; a second copy is sampled by the shaders when opaque geometry or the near
// plane cuts through cells. The float image is then composited over the scene.
// Front to back ("under", psi::DrawWay::FrontToBack) the same image is composited from the
// nearest tetrahedra on, with the depth test on, for PsiOpacityMasks to mask the pixels already
// opaque in it (GetImage) between chunks of the order (early ray termination).
#ifndef PsiRenderTarget_h
#define PsiRenderTarget_h

#include "PsiDepthPeelingCalls.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <memory>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class PsiRenderTarget
{
public:
  PsiRenderTarget();
  ~PsiRenderTarget();

  /// Sizes the target to the renderer's tile and copies the scene depth from the framebuffer
  /// being rendered, for the depth test, when `sceneDepth` (the scene has opaque geometry:
  /// psi::SceneHasOpaqueGeometry); with `sampleDepth` also the copy the shaders read. False for
  /// an empty tile.
  bool CaptureDepthTexture(
    vtkRenderer* ren, vtkOpenGLRenderWindow* renWin, bool sampleDepth, bool sceneDepth);
  /// Sets the shaders' `sceneDepth` sampler and `viewportSize` (after CaptureDepthTexture).
  void SetShaderParameters(vtkShaderProgram* program);
  /// Width and height of the target in pixels (after CaptureDepthTexture).
  const int* GetSize() const { return this->Size; }
  /// For each float image of depth-peeling stage `peelStage` (PsiDepthPeelingCalls::ImagesOf:
  /// 1, or 2 before the peels and in each peel), clears it and runs `drawImage(i)` into it with
  /// blending and the depth test set (all GL state restored afterwards); then composites the
  /// images into the framebuffer being rendered (PsiCompositeFS.glsl; `compositeParameters`
  /// sets the pass's uniforms on the composite program). `frontToBack`: "under" blending and
  /// the depth test on, for drawImage's PsiOpacityMasks (outside depth peeling only).
  void DrawAndComposite(vtkOpenGLRenderWindow* renWin, const std::function<void(int)>& drawImage,
    PsiDepthPeelingCalls::Stage peelStage,
    const std::function<void(vtkShaderProgram*)>& compositeParameters, bool frontToBack = false);
  /// The float image being drawn into (within drawImage; the first, outside depth peeling).
  vtkTextureObject* GetImage() const;
  void ReleaseGraphicsResources(vtkWindow* win);

private:
  PsiRenderTarget(const PsiRenderTarget&) = delete;
  void operator=(const PsiRenderTarget&) = delete;
  void Composite(vtkOpenGLRenderWindow* renWin, PsiDepthPeelingCalls::Stage peelStage,
    const std::function<void(vtkShaderProgram*)>& compositeParameters);
  void ReserveImages(vtkOpenGLRenderWindow* renWin, int images);
  void ClearDepth(vtkOpenGLState* ostate);

  vtkNew<vtkTextureObject> DepthTexture;
  vtkNew<vtkTextureObject> DepthSampleTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkTextureObject> FrontImage; // the second image, within depth peeling
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };
  bool SampleDepth = false;
  bool DepthTest = true; // the scene has opaque geometry to hide cells behind
};

#endif
