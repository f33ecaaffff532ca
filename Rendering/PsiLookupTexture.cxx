#include "PsiLookupTexture.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

PsiLookupTexture::PsiLookupTexture(const char* sampler)
  : Sampler(sampler)
{
}

PsiLookupTexture::~PsiLookupTexture() = default;

void PsiLookupTexture::Activate(vtkShaderProgram* program)
{
  this->Texture->Activate();
  program->SetUniformi(this->Sampler, this->Texture->GetTextureUnit());
  this->SetUniforms(program);
}

void PsiLookupTexture::Deactivate()
{
  this->Texture->Deactivate();
}

void PsiLookupTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Texture->ReleaseGraphicsResources(win);
  this->Forget();
}

vtkTextureObject* PsiLookupTexture::TextureIn(vtkOpenGLRenderWindow* renWin)
{
  this->Texture->SetContext(renWin);
  return this->Texture;
}

bool PsiLookupTexture::IsUploaded() const
{
  return this->Texture->GetHandle() != 0;
}

void PsiLookupTexture::SetLinearClamped(bool depth)
{
  vtkTextureObject* t = this->Texture;
  t->SetMinificationFilter(vtkTextureObject::Linear);
  t->SetMagnificationFilter(vtkTextureObject::Linear);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  if (depth)
  {
    t->SetWrapR(vtkTextureObject::ClampToEdge);
  }
}
