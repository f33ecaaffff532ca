#include "PsiGeometryProjector.h"

#include "PsiShaderComposer.h"
#include "PsiVisibilityOrder.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"

vtkShaderProgram* PsiGeometryProjector::ReadyProgram(
  vtkOpenGLRenderWindow* renWin, const psi::ShaderFeatures& f, const char* integrator, bool& built)
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

void PsiGeometryProjector::Draw(PsiVisibilityOrder& order, vtkShaderProgram* program,
  size_t targetPixels, const std::function<void(size_t first)>& beforeChunk) const
{
  // each tetrahedron is one point whose attribute is its four point ids (PsiVolumeVS.glsl)
  const GLint loc = glGetAttribLocation(static_cast<GLuint>(program->GetHandle()), "tetPointIds");
  if (loc < 0)
  {
    return;
  }
  glBindBuffer(GL_ARRAY_BUFFER, order.GetStreamBuffer());
  glEnableVertexAttribArray(static_cast<GLuint>(loc));
  glVertexAttribIPointer(static_cast<GLuint>(loc), 4, GL_UNSIGNED_INT, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  order.Draw([](size_t first, size_t count)
    { glDrawArrays(GL_POINTS, static_cast<GLint>(first), static_cast<GLsizei>(count)); },
    targetPixels, beforeChunk);
}

void PsiGeometryProjector::ReleaseGraphicsResources()
{
  this->Program = nullptr;
  this->Key.clear();
}
