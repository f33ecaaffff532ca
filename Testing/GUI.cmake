# XML-driven GUI regression tests (issue 6): pqevents scripts (the format of Tools > Record Test)
# replayed in the real `paraview` client, with image baselines under Testing/Data/Baseline/.
# Needs an X server: run ctest under xvfb-run, as for the other GL tests.
# paraview_add_client_tests() needs the ParaView::paraview target, which the Debian package does
# not export, so the equivalent command line is written out here (options of ParaView 5.11).
find_program(PARAVIEW_CLIENT_EXECUTABLE NAMES paraview)
if (NOT PARAVIEW_CLIENT_EXECUTABLE)
  message(STATUS "paraview client not found: GUI tests disabled")
  return ()
endif ()

set(psi_gui_tests PsiVolumeGUI)
foreach (name IN LISTS psi_gui_tests)
  set(test_dir "${CMAKE_BINARY_DIR}/Testing/Temporary/GUI/${name}")
  file(MAKE_DIRECTORY "${test_dir}")
  add_test(NAME PsiGUI.${name}
    COMMAND "${PARAVIEW_CLIENT_EXECUTABLE}" --dr
            "--plugin-search-paths=$<TARGET_FILE_DIR:PsiVolume>"
            --plugins=PsiVolume
            "--test-script=${CMAKE_CURRENT_SOURCE_DIR}/XML/${name}.xml"
            "--test-baseline=${CMAKE_CURRENT_SOURCE_DIR}/Data/Baseline/${name}.png"
            --test-threshold=5
            "--test-directory=${test_dir}"
            "--baseline-directory=${CMAKE_CURRENT_SOURCE_DIR}/Data/Baseline"
            --exit)
  set_tests_properties(PsiGUI.${name} PROPERTIES
    LABELS "GUI"
    TIMEOUT 120
    # QtTesting prints this when a widget path does not exist in this ParaView version.
    FAIL_REGULAR_EXPRESSION "Couldn't find object|Failed to parse"
    RESOURCE_LOCK PsiGUI)
endforeach ()
