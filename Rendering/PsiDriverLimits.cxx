#include "PsiDriverLimits.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides

PsiDriverLimits PsiDriverLimits::Query()
{
  PsiDriverLimits l;
  GLint texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
  l.MaxTextureBufferTexels = texels;
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major > 4 || (major == 4 && minor >= 3))
  {
    GLint64 bytes = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
    l.MaxStorageBlockBytes = static_cast<long long>(bytes);
  }
  return l;
}
