# The Rendering module, and the Core it builds on, wrapped for Python with the found VTK's
# wrappers: vtkPsiVolumeMapper renders from plain VTK Python (`vtkmodules`, no ParaView), the way
# VTK's own mappers do:
#   from psivolume_vtk.PsiVolumeRendering import vtkPsiVolumeMapper
# The extension modules go beside the psivolume package (PSI_PYTHON_DESTINATION), in the
# namespace package psivolume_vtk, and load the plugin's module libraries from its folder.
if (NOT (PARAVIEW_USE_PYTHON AND TARGET VTK::WrapPython))
  return ()
endif ()
vtk_module_wrap_python(
  MODULES             PsiVolume::Core PsiVolume::Rendering
  TARGET              PsiVolumeVTKPython
  PYTHON_PACKAGE      "psivolume_vtk"
  MODULE_DESTINATION  "${PSI_PYTHON_DESTINATION}"
  LIBRARY_DESTINATION "${PSI_PLUGINS_DIR}/PsiVolume"
  CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/psivolume"
  INSTALL_HEADERS     OFF
  BUILD_STATIC        OFF
  COMPONENT           runtime)
# (as for the ClientServer wrappers, Plugin/CMakeLists.txt)
psi_wrappers_depend_on_setting_list(
  "${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/PsiVolumeRenderingPython/vtkPsiVolumeMapperPython.cxx")
