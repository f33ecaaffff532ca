#include "PsiRenderTarget.h"

#include "PsiCompositeFS.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

PsiRenderTarget::PsiRenderTarget() = default;

PsiRenderTarget::~PsiRenderTarget() = default;

bool PsiRenderTarget::CaptureDepthTexture(
  vtkRenderer* ren, vtkOpenGLRenderWindow* renWin, bool sampleDepth, bool sceneDepth)
{
  int w, h, x0, y0;
  ren->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  if (w <= 0 || h <= 0)
  {
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  this->DepthTexture->SetContext(renWin);
  this->DepthSampleTexture->SetContext(renWin);
  if (this->Size[0] != w || this->Size[1] != h || !this->Framebuffer)
  {
    this->DepthTexture->AllocateDepth(w, h, vtkTextureObject::Float32);
    this->DepthSampleTexture->AllocateDepth(w, h, vtkTextureObject::Float32);
    ostate->PushFramebufferBindings();
    if (!this->Framebuffer)
    {
      this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->Framebuffer->SetContext(renWin);
      this->Framebuffer->PopulateFramebuffer(w, h, true, 1, VTK_FLOAT, false, 0, 0);
    }
    this->Framebuffer->Bind();
    this->Framebuffer->Resize(w, h);
    this->Framebuffer->AddDepthAttachment(this->DepthTexture);
    ostate->PopFramebufferBindings();
    this->Size[0] = w;
    this->Size[1] = h;
  }
  this->Origin[0] = x0;
  this->Origin[1] = y0;
  // the scene's depth, read from the framebuffer bound for reading (the one being rendered);
  // without opaque geometry it is the far plane everywhere, and the depth test is skipped
  this->DepthTest = sampleDepth || sceneDepth;
  if (this->DepthTest)
  {
    this->DepthTexture->Activate();
    this->DepthTexture->CopyFromFrameBuffer(x0, y0, 0, 0, w, h);
    this->DepthTexture->Deactivate();
  }
  this->SampleDepth = sampleDepth;
  if (sampleDepth)
  {
    this->DepthSampleTexture->Activate();
    this->DepthSampleTexture->CopyFromFrameBuffer(x0, y0, 0, 0, w, h);
  }
  return true;
}

void PsiRenderTarget::SetShaderParameters(vtkShaderProgram* program)
{
  if (this->SampleDepth)
  {
    program->SetUniformi("sceneDepth", this->DepthSampleTexture->GetTextureUnit());
  }
  const float viewport[2] = { static_cast<float>(this->Size[0]),
    static_cast<float>(this->Size[1]) };
  program->SetUniform2f("viewportSize", viewport);
}

// The second color attachment, sized as the first, when two images are drawn.
void PsiRenderTarget::ReserveImages(vtkOpenGLRenderWindow* renWin, int images)
{
  if (images < 2)
  {
    return;
  }
  this->FrontImage->SetContext(renWin);
  if (static_cast<int>(this->FrontImage->GetWidth()) != this->Size[0] ||
    static_cast<int>(this->FrontImage->GetHeight()) != this->Size[1] ||
    !this->FrontImage->GetHandle())
  {
    this->FrontImage->SetInternalFormat(GL_RGBA32F);
    this->FrontImage->SetFormat(GL_RGBA);
    this->FrontImage->Allocate2D(this->Size[0], this->Size[1], 4, VTK_FLOAT);
  }
  this->Framebuffer->AddColorAttachment(1, this->FrontImage);
}

void PsiRenderTarget::DrawAndComposite(vtkOpenGLRenderWindow* renWin,
  const std::function<void(int)>& drawImage, PsiDepthPeelingCalls::Stage peelStage,
  const std::function<void(vtkShaderProgram*)>& compositeParameters, bool frontToBack)
{
  const int images = PsiDepthPeelingCalls::ImagesOf(peelStage);
  vtkOpenGLState* ostate = renWin->GetState();
  {
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cull(ostate, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglClearColor clearColor(ostate);

    ostate->PushFramebufferBindings();
    this->Framebuffer->Bind();
    this->ReserveImages(renWin, images);
    ostate->vtkglViewport(0, 0, this->Size[0], this->Size[1]);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglClearColor(0, 0, 0, 0);
    // the depth test against the scene's opaque geometry, and front to back against the mask
    if (frontToBack && !this->DepthTest)
    {
      this->ClearDepth(ostate); // no scene depth was copied: the far plane everywhere
    }
    if (this->DepthTest || frontToBack)
    {
      ostate->vtkglEnable(GL_DEPTH_TEST);
    }
    else
    {
      ostate->vtkglDisable(GL_DEPTH_TEST);
    }
    ostate->vtkglDepthFunc(GL_LESS);
    ostate->vtkglDepthMask(GL_FALSE);
    ostate->vtkglDisable(GL_CULL_FACE);
    ostate->vtkglEnable(GL_BLEND);
    // premultiplied, added (a caller such as VTK's dual depth peeling may have left GL_MAX,
    // which the composite below keeps): back to front "over", dst = src + (1 - a_src) dst; front
    // to back "under", dst = dst + (1 - a_dst) src (Moreland's dissertation §2.2.3)
    GLint equation[2] = { GL_FUNC_ADD, GL_FUNC_ADD };
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &equation[0]);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &equation[1]);
    ostate->vtkglBlendEquation(GL_FUNC_ADD);
    if (frontToBack)
    {
      ostate->vtkglBlendFuncSeparate(
        GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
    }
    else
    {
      ostate->vtkglBlendFuncSeparate(
        GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
    for (int i = 0; i < images; ++i)
    {
      this->Framebuffer->ActivateDrawBuffer(i);
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
      drawImage(i);
    }
    ostate->vtkglBlendEquationSeparate(equation[0], equation[1]);
    ostate->PopFramebufferBindings();

    // within depth peeling the pass's own framebuffer, at the origin, receives the images
    const bool own = peelStage > PsiDepthPeelingCalls::Plain;
    ostate->vtkglViewport(
      own ? 0 : this->Origin[0], own ? 0 : this->Origin[1], this->Size[0], this->Size[1]);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    // the premultiplied images go "over" what the framebuffer holds, whichever way they were drawn
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    this->Composite(renWin, peelStage, compositeParameters);
  }
  if (this->SampleDepth)
  {
    this->DepthSampleTexture->Deactivate();
  }
}

// The depth attachment at the far plane (1), the clear value restored.
void PsiRenderTarget::ClearDepth(vtkOpenGLState* ostate)
{
  GLfloat clearDepth = 1;
  glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clearDepth);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  ostate->vtkglClearDepth(clearDepth);
}

vtkTextureObject* PsiRenderTarget::GetImage() const
{
  return this->Framebuffer ? this->Framebuffer->GetColorAttachmentAsTextureObject(0) : nullptr;
}

// The volume images (premultiplied) into the framebuffer being rendered, with the blending the
// caller set: over the scene, or into the depth-peeling pass's buffers (PsiCompositeFS.glsl).
void PsiRenderTarget::Composite(vtkOpenGLRenderWindow* renWin,
  PsiDepthPeelingCalls::Stage peelStage,
  const std::function<void(vtkShaderProgram*)>& compositeParameters)
{
  const int images = PsiDepthPeelingCalls::ImagesOf(peelStage);
  if (!this->CompositeQuad)
  {
    this->CompositeQuad.reset(new vtkOpenGLQuadHelper(renWin, nullptr, PsiCompositeFS, ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->CompositeQuad->Program);
  }
  vtkShaderProgram* program = this->CompositeQuad->Program;
  if (!program)
  {
    return;
  }
  vtkTextureObject* back = this->Framebuffer->GetColorAttachmentAsTextureObject(0);
  back->Activate();
  program->SetUniformi("volumeImage", back->GetTextureUnit());
  if (images > 1)
  {
    this->FrontImage->Activate();
    program->SetUniformi("frontImage", this->FrontImage->GetTextureUnit());
  }
  program->SetUniformi("peelStage", peelStage);
  compositeParameters(program);
  this->CompositeQuad->Render();
  back->Deactivate();
  if (images > 1)
  {
    this->FrontImage->Deactivate();
  }
}

void PsiRenderTarget::ReleaseGraphicsResources(vtkWindow* win)
{
  this->DepthTexture->ReleaseGraphicsResources(win);
  this->DepthSampleTexture->ReleaseGraphicsResources(win);
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(win);
    this->Framebuffer = nullptr;
    this->FrontImage->ReleaseGraphicsResources(win);
  }
  this->CompositeQuad.reset();
  this->Size[0] = this->Size[1] = 0;
}
