/**
 * What the plugin does for ParaView's Python when it is loaded (an INITIALIZERS function of
 * paraview_add_plugin, Plugin/CMakeLists.txt): from a build tree, it puts the checkout's Python/
 * folder on sys.path, so that `import psivolume` works after LoadPlugin in pvpython, pvbatch
 * and the GUI's Python shell as it does with an installed plugin (whose package is installed
 * beside ParaView's own Python modules, cmake/PsiVolumeInstall.cmake). The installed plugin adds
 * nothing: it is not at the build tree's plugin path.
 */
#ifndef PsiPluginPython_h
#define PsiPluginPython_h

void psiPluginPythonPath();

#endif
