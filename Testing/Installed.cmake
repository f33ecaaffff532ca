# What an install changes, checked from the install tree: `cmake --install` into
# <build>/Testing/installed (the fixture PsiInstalled.install, run before any test that needs it),
# then the scripts that Python.cmake marks INSTALLED: the plugin loaded by the ranks of pvbatch
# under MPI and by a pvserver's ranks, with PYTHONPATH naming only the installed package and no
# PSI_* override (psivolume finds the installed plugin, installed_paths.py). PsiPython.installed
# (Testing/Install/run_installed.py) checks the rest of an install in pvpython: the files, the
# plugin and psivolume from the tree, 'Psi Volume', the installed reference renderer and reader.
# The other tests run once, from the build tree: an install changes none of what they check.
set(_psi_tree "${CMAKE_BINARY_DIR}/Testing/installed")
add_test(NAME PsiInstalled.install
  COMMAND "${CMAKE_COMMAND}" --install "${CMAKE_BINARY_DIR}" --prefix "${_psi_tree}")
set_tests_properties(PsiInstalled.install PROPERTIES FIXTURES_SETUP PsiInstallTree)
# After the test's own ENVIRONMENT, so that these win over any PSI_* it names.
set(_psi_installed_environment "PYTHONPATH=${_psi_tree}/${PSI_PYTHON_DESTINATION}" "PSI_PLUGIN="
  "PSI_REFERENCE_RENDER=" "PSI_DATA_DIR=${PSI_DATA_DIR}")

# psi_add_installed_test(NAME TIMEOUT s [ENVIRONMENT ...] COMMAND ...): PsiInstalled.NAME, the
# command of PsiPython.NAME run from the install tree.
function(psi_add_installed_test name)
  cmake_parse_arguments(arg "" "TIMEOUT" "ENVIRONMENT;COMMAND" ${ARGN})
  add_test(NAME PsiInstalled.${name} COMMAND ${arg_COMMAND})
  set(environment ${arg_ENVIRONMENT} ${_psi_installed_environment})
  set_tests_properties(PsiInstalled.${name} PROPERTIES
    ENVIRONMENT "${environment}"
    FIXTURES_REQUIRED PsiInstallTree
    SKIP_RETURN_CODE 77
    TIMEOUT ${arg_TIMEOUT})
endfunction ()
