#include "PsiPluginPython.h"

#include <vtkPythonInterpreter.h>
#include <vtksys/SystemTools.hxx>

#include <dlfcn.h>

#include <string>

// Both defined by Plugin/CMakeLists.txt: where the build tree puts this plugin, and the
// checkout's folder holding the package psivolume.
#ifndef PSI_BUILD_PLUGIN_DIR
#error "PSI_BUILD_PLUGIN_DIR must be defined"
#endif
#ifndef PSI_SOURCE_PYTHON_DIR
#error "PSI_SOURCE_PYTHON_DIR must be defined"
#endif

namespace
{
// The directory of the shared library this function is in (empty when unknown).
std::string LoadedFromDirectory()
{
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&psiPluginPythonPath), &info) == 0 || !info.dli_fname)
  {
    return std::string();
  }
  return vtksys::SystemTools::GetFilenamePath(
    vtksys::SystemTools::GetRealPath(info.dli_fname));
}
}

void psiPluginPythonPath()
{
  const std::string here = LoadedFromDirectory();
  if (here.empty() || here != vtksys::SystemTools::GetRealPath(PSI_BUILD_PLUGIN_DIR))
  {
    return;
  }
  // Before Python starts (the GUI loads plugins first), the path is kept and added when it does;
  // a path already on sys.path (PYTHONPATH) is not added twice.
  vtkPythonInterpreter::PrependPythonPath(PSI_SOURCE_PYTHON_DIR);
}
