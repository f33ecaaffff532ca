#include "PsiPluginPython.h"

#include <vtkPythonInterpreter.h>
#include <vtksys/SystemTools.hxx>

#include <dlfcn.h>

#include <string>

// Defined by Plugin/CMakeLists.txt: where the build tree puts this plugin, the checkout's folder
// holding the package psivolume, and the installed package's folder relative to the installed
// plugin's (or absolute).
#if !defined(PSI_BUILD_PLUGIN_DIR) || !defined(PSI_SOURCE_PYTHON_DIR) ||                           \
  !defined(PSI_INSTALLED_PYTHON_DIR)
#error "PSI_BUILD_PLUGIN_DIR, PSI_SOURCE_PYTHON_DIR and PSI_INSTALLED_PYTHON_DIR must be defined"
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
  return vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::GetRealPath(info.dli_fname));
}

// The folder holding psivolume for a plugin loaded from `here` (empty when there is none).
std::string PackageFolder(const std::string& here)
{
  if (here == vtksys::SystemTools::GetRealPath(PSI_BUILD_PLUGIN_DIR))
  {
    return PSI_SOURCE_PYTHON_DIR;
  }
  const std::string installed =
    vtksys::SystemTools::CollapseFullPath(PSI_INSTALLED_PYTHON_DIR, here);
  if (vtksys::SystemTools::FileExists(installed + "/psivolume/__init__.py", true))
  {
    return installed;
  }
  return std::string();
}
}

void psiPluginPythonPath()
{
  const std::string here = LoadedFromDirectory();
  const std::string folder = here.empty() ? here : PackageFolder(here);
  if (!folder.empty())
  {
    // Before Python starts (the GUI loads plugins first), the path is kept and added when it
    // does; a path already on sys.path (PYTHONPATH, ParaView's own) is not added twice.
    vtkPythonInterpreter::PrependPythonPath(folder.c_str());
  }
}
