#include "PsiOpacityMasks.h"

#include "PsiFramePlan.h" // psi::SaturatedOpacity
#include "PsiOpaqueMaskFS.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

PsiOpacityMasks::PsiOpacityMasks() = default;

PsiOpacityMasks::~PsiOpacityMasks() = default;

bool PsiOpacityMasks::IsSupported()
{
  return glTextureBarrier != nullptr;
}

void PsiOpacityMasks::Begin(vtkTextureObject* image, size_t tets, size_t chunk, int masksPerFrame)
{
  this->Image = image;
  this->Stride = this->Next = StrideTets(tets, chunk, masksPerFrame);
}

// Whether the previous mask of this image found opaque pixels (true before the first). Its
// count is read when the next mask is due, a stride later: waiting for it then costs less than
// the masks its answer saves (llvmpipe had never finished it by then without the wait).
bool PsiOpacityMasks::PreviousFoundOpaque()
{
  if (!this->Samples.IsPending())
  {
    return true;
  }
  return this->Samples.Take() > 0;
}

void PsiOpacityMasks::Mask(
  size_t first, vtkOpenGLRenderWindow* renWin, vtkShaderProgram* drawProgram)
{
  this->Stride *= this->PreviousFoundOpaque() ? 1 : 2;
  this->Next = first + this->Stride;
  vtkOpenGLState* ostate = renWin->GetState();
  GLint vertexArray = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
  // a projector may have bound its programs without VTK's shader cache (the compute projector):
  // the cache must not take the mask's program for bound
  renWin->GetShaderCache()->ReleaseCurrentShader();
  if (!this->Quad)
  {
    this->Quad.reset(new vtkOpenGLQuadHelper(renWin, nullptr, PsiOpaqueMaskFS, ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  vtkShaderProgram* program = this->Quad->Program;
  if (program)
  {
    // the image is read where it is drawn: the barrier makes the draws so far visible
    glTextureBarrier();
    vtkOpenGLState::ScopedglColorMask colorMask(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    ostate->vtkglDepthMask(GL_TRUE);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    this->Image->Activate();
    program->SetUniformi("volumeImage", this->Image->GetTextureUnit());
    program->SetUniformf("saturatedOpacity", static_cast<float>(psi::SaturatedOpacity));
    this->Samples.Begin(); // the pixels it finds opaque
    this->Quad->Render();
    this->Samples.End();
    this->Image->Deactivate();
  }
  if (drawProgram)
  {
    renWin->GetShaderCache()->ReadyShaderProgram(drawProgram);
  }
  glBindVertexArray(static_cast<GLuint>(vertexArray));
}

void PsiOpacityMasks::End()
{
  this->PreviousFoundOpaque();
  this->Image = nullptr;
}

void PsiOpacityMasks::ReleaseGraphicsResources(vtkWindow*)
{
  this->Quad.reset();
  this->Samples.ReleaseGraphicsResources();
  this->Image = nullptr;
}
