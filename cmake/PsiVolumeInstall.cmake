# What `cmake --install` puts beside the plugin (docs/install.md): the project's Python package
# where ParaView's own Python modules are and the reference renderer of the accuracy report in the
# plugin's directory (the Debian package adds its own files: cmake/PsiVolumePackaging.cmake).
# paraview_plugin_build (CMakeLists.txt) installs the plugin, its modules and PsiVolume.plugins.xml.

# The Python package (Python/psivolume) at PSI_PYTHON_DESTINATION (CMakeLists.txt).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/Python/psivolume"
  DESTINATION "${PSI_PYTHON_DESTINATION}"
  COMPONENT   runtime
  FILES_MATCHING PATTERN "*.py"
  PATTERN "__pycache__" EXCLUDE)

# The installed package finds the installed plugin (psivolume.data.find_plugin) by this path,
# relative to the package, so that the install tree can be moved (DESTDIR, a package).
file(RELATIVE_PATH _psi_plugin_from_package
  "/prefix/${PSI_PYTHON_DESTINATION}/psivolume"
  "/prefix/${PSI_PLUGINS_DIR}/PsiVolume/PsiVolume.so")
set(_psi_installed_paths "${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/psivolume_installed_paths.py")
file(WRITE "${_psi_installed_paths}"
  "\"\"\"Written by `cmake --install`: where the plugin is, relative to this package.\"\"\"\n"
  "PLUGIN = \"${_psi_plugin_from_package}\"\n")
install(FILES "${_psi_installed_paths}"
  DESTINATION "${PSI_PYTHON_DESTINATION}/psivolume"
  RENAME      installed_paths.py
  COMPONENT   runtime)

# The exact reference of the accuracy report (psivolume.accuracy), beside the plugin whose
# libPsiVolumeCore.so it links.
set_target_properties(psi_reference_render PROPERTIES INSTALL_RPATH "\$ORIGIN")
install(TARGETS psi_reference_render
  RUNTIME DESTINATION "${PSI_PLUGINS_DIR}/PsiVolume"
  COMPONENT runtime)
