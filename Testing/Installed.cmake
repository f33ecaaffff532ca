# The smoke set against the install tree: `cmake --install` into <build>/Testing/installed (the
# fixture PsiInstalled.install, run before any test that needs it), then the same pvpython,
# pvbatch and pvserver scripts as PsiPython.*, with PYTHONPATH naming only the installed package
# and no PSI_* override: psivolume finds the installed plugin (installed_paths.py) and the
# reference renderer beside it, so a plugin that works only from the build tree fails here.
set(_psi_tree "${CMAKE_BINARY_DIR}/Testing/installed")
add_test(NAME PsiInstalled.install
  COMMAND "${CMAKE_COMMAND}" --install "${CMAKE_BINARY_DIR}" --prefix "${_psi_tree}")
set_tests_properties(PsiInstalled.install PROPERTIES FIXTURES_SETUP PsiInstallTree)
set(_psi_installed_environment "PYTHONPATH=${_psi_tree}/${PSI_PYTHON_DESTINATION}" "PSI_PLUGIN="
  "PSI_REFERENCE_RENDER=" "PSI_BUILD_DIR=" "PSI_DATA_DIR=${PSI_DATA_DIR}")

# psi_add_installed_test(NAME [RUN_SERIAL] [ENVIRONMENT ...] COMMAND ...): PsiInstalled.NAME.
function(psi_add_installed_test name)
  cmake_parse_arguments(arg "RUN_SERIAL" "" "ENVIRONMENT;COMMAND" ${ARGN})
  add_test(NAME PsiInstalled.${name} COMMAND ${arg_COMMAND})
  set_tests_properties(PsiInstalled.${name} PROPERTIES
    ENVIRONMENT "${_psi_installed_environment};${arg_ENVIRONMENT}"
    FIXTURES_REQUIRED PsiInstallTree
    SKIP_RETURN_CODE 77
    TIMEOUT 300
    RUN_SERIAL ${arg_RUN_SERIAL})
endfunction ()

set(_psi_scripts "${CMAKE_CURRENT_SOURCE_DIR}/Python")
set(_psi_pvpython "${PVPYTHON_EXECUTABLE}" --force-offscreen-rendering)
psi_add_installed_test(plugin_basics COMMAND ${_psi_pvpython} "${_psi_scripts}/test_plugin_basics.py")
psi_add_installed_test(bad_input.reader
  COMMAND ${_psi_pvpython} "${_psi_scripts}/test_bad_input.py" reader)
psi_add_installed_test(interaction COMMAND ${_psi_pvpython} "${_psi_scripts}/test_interaction.py")
psi_add_installed_test(accuracy_report
  COMMAND ${_psi_pvpython} "${_psi_scripts}/test_accuracy_report.py")
if (PVBATCH_EXECUTABLE AND MPIEXEC_EXECUTABLE)
  foreach (name IN ITEMS mpi mpi_lod)
    psi_add_installed_test(${name} RUN_SERIAL
      ENVIRONMENT "PSI_PVBATCH=${PVBATCH_EXECUTABLE}" "OMPI_MCA_rmaps_base_oversubscribe=1"
      COMMAND "${MPIEXEC_EXECUTABLE}" --allow-run-as-root -n 2 "${PVBATCH_EXECUTABLE}"
              --force-offscreen-rendering "${_psi_scripts}/test_${name}.py")
  endforeach ()
endif ()
if (PVSERVER_EXECUTABLE AND MPIEXEC_EXECUTABLE)
  psi_add_installed_test(pvserver RUN_SERIAL
    ENVIRONMENT "PSI_PVSERVER=${PVSERVER_EXECUTABLE}" "PSI_MPIEXEC=${MPIEXEC_EXECUTABLE}"
                "OMPI_MCA_rmaps_base_oversubscribe=1"
    COMMAND ${_psi_pvpython} "${_psi_scripts}/test_pvserver.py")
endif ()
