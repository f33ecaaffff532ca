/**
 * What the plugin does for ParaView's Python when it is loaded (an INITIALIZERS function of
 * paraview_add_plugin, Plugin/CMakeLists.txt): it puts the folder holding the package psivolume
 * on sys.path, so that `import psivolume` works after LoadPlugin in pvpython, pvbatch and the
 * GUI's Python shell with no PYTHONPATH:
 *  - loaded from the build tree (the plugin is where the build put it): the checkout's Python/;
 *  - installed: the package's install folder, found relative to the plugin's own (both
 *    relative to the prefix, PSI_PYTHON_DESTINATION and PSI_PLUGINS_DIR), when it holds the
 *    package. By default that is ParaView's own Python folder, already on sys.path: nothing
 *    changes then (a folder already on sys.path is not added again).
 */
#ifndef PsiPluginPython_h
#define PsiPluginPython_h

void psiPluginPythonPath();

#endif
