/**
 * The OpenGL function loader of the VTK the plugin is built against: GLEW (`vtk_glew.h`) up to
 * VTK 9.3, glad (`vtk_glad.h`) from VTK 9.4 on. Rendering/CMakeLists.txt links the one
 * the found VTK provides and defines PSI_GL_LOADER_GLAD when it is glad.
 */
#ifndef PsiOpenGL_h
#define PsiOpenGL_h

#if defined(PSI_GL_LOADER_GLAD) && PSI_GL_LOADER_GLAD
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#endif
