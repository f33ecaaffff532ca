// PsiLookupTexture: a GPU table held in one texture, the base of the lookup textures
// (PsiTableTextures.h), as VTK's vtkOpenGLVolumeLookupTable is the base of its volume mapper's
// color and opacity tables. The base owns the texture and does what is the same for every such
// table: Activate binds the texture and points the table's sampler uniform at its unit before the
// table sets its other uniforms (SetUniforms); Deactivate unbinds it; ReleaseGraphicsResources
// releases it and has the table forget what it held (Forget), so that its next NeedsUpdate says
// yes. Each table keeps its own NeedsUpdate and Update: what it holds, and when that changes.
#ifndef PsiLookupTexture_h
#define PsiLookupTexture_h

#include "PsiGpuTable.h"

#include "vtkNew.h"

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class PsiLookupTexture : public PsiGpuTable
{
public:
  ~PsiLookupTexture() override;
  void Activate(vtkShaderProgram* program) final;
  void Deactivate() final;
  void ReleaseGraphicsResources(vtkWindow* win) final;

protected:
  /// `sampler`: the uniform through which the table's GLSL reads the texture.
  explicit PsiLookupTexture(const char* sampler);
  /// The uniforms of the table's GLSL other than its sampler (called by Activate).
  virtual void SetUniforms(vtkShaderProgram* program) = 0;
  /// Forgets what the released texture held (called by ReleaseGraphicsResources).
  virtual void Forget() = 0;
  /// The texture, in the context of `renWin`, for Update to fill.
  vtkTextureObject* TextureIn(vtkOpenGLRenderWindow* renWin);
  /// Whether the texture holds data on the GPU.
  bool IsUploaded() const;
  /// Linear filtering, clamped at the edges of S and T (and of R, `depth`).
  void SetLinearClamped(bool depth = false);

private:
  vtkNew<vtkTextureObject> Texture;
  const char* Sampler;
};

#endif
