# GUI tests of the properties-panel read-out of the last 'Psi Volume' frame (pqPsiFrameStatsWidget):
# a pqevents script replayed in the real `paraview` client, whose pqcheck steps read the read-out
# widget (Testing/XML/PsiVolumePanel.xml), in the builtin session and in a client/server session.
# Registered through ParaView's own test functions (ParaViewTesting.cmake, found with ParaView):
# paraview_add_client_tests and paraview_add_client_server_tests run the client under ParaView's
# smTestDriver, which for the second starts a pvserver with the plugin and connects the client
# to it, so the read-out must come from the server, which renders. Need an X server (run ctest
# under xvfb-run) and a ParaView built with Qt, as the widget does. The script also compares the
# read-out's numbers with the representation's information properties through the Python shell
# (XML/PsiGUICheck.py's check_readout, found under --data-directory as $PARAVIEW_DATA_ROOT).
if (NOT PARAVIEW_USE_QT)
  return ()
endif ()
if (NOT TARGET ParaView::paraview OR NOT TARGET ParaView::smTestDriver)
  message(STATUS "ParaView's client or smTestDriver not found: panel GUI tests disabled")
  return ()
endif ()

set(psi_panel_test_dir "${CMAKE_BINARY_DIR}/Testing/Temporary/GUI/PsiVolumePanel")
file(MAKE_DIRECTORY "${psi_panel_test_dir}")
set(PsiVolumePanel_USES_DIRECT_DATA ON) # no ExternalData: the script compares no image
set(psi_panel_args
  LOAD_PLUGIN PsiVolume
  PLUGIN_PATH "$<TARGET_FILE_DIR:PsiVolume>"
  TEST_DIRECTORY "${psi_panel_test_dir}"
  DATA_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
  TEST_SCRIPTS "${CMAKE_CURRENT_SOURCE_DIR}/XML/PsiVolumePanel.xml")
paraview_add_client_tests(PREFIX PsiGUI ${psi_panel_args})
# smTestDriver starts the server under mpiexec (ParaView is built with MPI): as root too, and
# with 2 ranks on fewer cores.
paraview_add_client_server_tests(PREFIX PsiGUI.ClientServer ${psi_panel_args}
  ENVIRONMENT OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
              OMPI_MCA_rmaps_base_oversubscribe=1)

# The project's Python package on PYTHONPATH, as for every test that runs ParaView (appended:
# ParaView's functions set these tests' ENVIRONMENT, the MPI variables above).
set_property(TEST PsiGUI.PsiVolumePanel PsiGUI.ClientServer.PsiVolumePanel APPEND PROPERTY
  ENVIRONMENT "${PSI_PYTHONPATH}")
set_tests_properties(PsiGUI.PsiVolumePanel PsiGUI.ClientServer.PsiVolumePanel PROPERTIES
  LABELS "GUI"
  TIMEOUT 240
  # QtTesting prints these when a widget path does not exist or a pqcheck fails; a failed check
  # also makes paraview exit non-zero, and smTestDriver with it. "PsiGUICheck FAILED": a read-out
  # check of the Python shell, whose result does not reach the exit code.
  FAIL_REGULAR_EXPRESSION "Couldn't find object|Failed to parse|Expecting:|Unhandled|PsiGUICheck FAILED"
  RESOURCE_LOCK PsiGUI)
