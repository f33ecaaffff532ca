# Headless rendering for compute nodes: no X server, OpenGL through EGL on a surfaceless Mesa
# llvmpipe. ParaView 6 chooses its OpenGL window at run time (VTK_DEFAULT_OPENGL_WINDOW), and
# Mesa 26 no longer ships OSMesa, so EGL is the way pvbatch renders without a display there.
# The tests run with DISPLAY removed, so an X window cannot stand in: the image check against
# the exact ray caster (test_plugin_basics.py) and the 2-rank MPI test (test_mpi.py).
# Included from Testing/CMakeLists.txt (which finds pvbatch and mpiexec); registered where
# ParaView is 6.0 or newer.
if (ParaView_VERSION VERSION_LESS "6.0")
  return ()
endif ()
if (NOT PVBATCH_EXECUTABLE)
  message(STATUS "pvbatch not found: headless EGL tests not registered")
  return ()
endif ()
set(psi_headless env -u DISPLAY VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow)
add_test(NAME PsiHeadless.plugin_basics
  COMMAND ${psi_headless} "${PVBATCH_EXECUTABLE}"
          "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_plugin_basics.py")
set_tests_properties(PsiHeadless.plugin_basics PROPERTIES
  ENVIRONMENT "PSI_PLUGIN=$<TARGET_FILE:PsiVolume>;${PSI_PYTHONPATH};PSI_DATA_DIR=${PSI_DATA_DIR}"
  SKIP_RETURN_CODE 77
  TIMEOUT 600)
if (MPIEXEC_EXECUTABLE)
  add_test(NAME PsiHeadless.mpi
    COMMAND ${psi_headless} ${PSI_MPI_WATCHDOG_COMMAND} "${MPIEXEC_EXECUTABLE}"
            --allow-run-as-root -n 2
            "${PVBATCH_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_mpi.py")
  set_tests_properties(PsiHeadless.mpi PROPERTIES
    ENVIRONMENT "PSI_PLUGIN=$<TARGET_FILE:PsiVolume>;${PSI_PYTHONPATH};PSI_DATA_DIR=${PSI_DATA_DIR};PSI_PVBATCH=${PVBATCH_EXECUTABLE};OMPI_MCA_rmaps_base_oversubscribe=1"
    SKIP_RETURN_CODE 77
    TIMEOUT ${PSI_MPI_TEST_TIMEOUT}
    RUN_SERIAL ON)
endif ()
