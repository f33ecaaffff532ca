#include "PsiGeometryProjector.h"

#include "PsiShaderComposer.h"
#include "PsiVisibilityOrder.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"

vtkShaderProgram* PsiGeometryProjector::ReadyProgram(vtkOpenGLRenderWindow* renWin,
  const psi::ShaderFeatures& f, const char* integrator, bool& built)
{
  vtkOpenGLShaderCache* cache = renWin->GetShaderCache();
  const std::string key = f.Key();
  built = !this->Program || this->Key != key;
  if (!built)
  {
    cache->ReadyShaderProgram(this->Program);
    return this->Program;
  }
  const psi::ShaderSources src = psi::ComposeShaders(f, integrator);
  this->Program =
    cache->ReadyShaderProgram(src.Vertex.c_str(), src.Fragment.c_str(), src.Geometry.c_str());
  this->Key = this->Program ? key : std::string();
  return this->Program;
}

void PsiGeometryProjector::Draw(PsiVisibilityOrder& order) const
{
  order.Draw();
}

void PsiGeometryProjector::ReleaseGraphicsResources()
{
  this->Program = nullptr;
  this->Key.clear();
}
