# GUI tests of the properties-panel read-out of the last 'Psi Volume' frame (pqPsiFrameStatsWidget):
# a pqevents script replayed in the real `paraview` client, whose pqcheck steps read the read-out
# widget (Testing/XML/PsiVolumePanel.xml), in the builtin session and in a client/server session
# with a local pvserver. Need an X server (run ctest under xvfb-run) and a ParaView built with Qt,
# as the widget does.
if (NOT PARAVIEW_USE_QT)
  return ()
endif ()
find_program(PARAVIEW_CLIENT_EXECUTABLE NAMES paraview)
if (NOT PARAVIEW_CLIENT_EXECUTABLE)
  message(STATUS "paraview client not found: panel GUI test disabled")
  return ()
endif ()

set(psi_panel_script "${CMAKE_CURRENT_SOURCE_DIR}/XML/PsiVolumePanel.xml")
set(psi_panel_test_dir "${CMAKE_BINARY_DIR}/Testing/Temporary/GUI/PsiVolumePanel")
file(MAKE_DIRECTORY "${psi_panel_test_dir}")
add_test(NAME PsiGUI.PsiVolumePanel
  COMMAND "${PARAVIEW_CLIENT_EXECUTABLE}" --dr
          "--plugin-search-paths=$<TARGET_FILE_DIR:PsiVolume>"
          --plugins=PsiVolume
          "--test-script=${psi_panel_script}"
          "--test-directory=${psi_panel_test_dir}"
          --exit)
set(psi_panel_tests PsiGUI.PsiVolumePanel)

# The same script against a pvserver: the read-out must come from the server, which renders.
find_program(PVSERVER_EXECUTABLE NAMES pvserver)
find_package(Python3 COMPONENTS Interpreter QUIET)
if (PVSERVER_EXECUTABLE AND Python3_Interpreter_FOUND)
  add_test(NAME PsiGUI.PsiVolumePanelClientServer
    COMMAND "${Python3_EXECUTABLE}"
            "${CMAKE_CURRENT_SOURCE_DIR}/Python/run_gui_client_server.py"
            "${PVSERVER_EXECUTABLE}" "${PARAVIEW_CLIENT_EXECUTABLE}"
            "$<TARGET_FILE_DIR:PsiVolume>" "${psi_panel_script}" "${psi_panel_test_dir}")
  list(APPEND psi_panel_tests PsiGUI.PsiVolumePanelClientServer)
endif ()

set_tests_properties(${psi_panel_tests} PROPERTIES
  LABELS "GUI"
  TIMEOUT 240
  # QtTesting prints these when a widget path does not exist or a pqcheck fails; a failed check
  # also makes paraview exit non-zero.
  FAIL_REGULAR_EXPRESSION "Couldn't find object|Failed to parse|Expecting:|Unhandled"
  RESOURCE_LOCK PsiGUI)
