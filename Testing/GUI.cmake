# XML-driven GUI regression tests: pqevents scripts (the format of Tools > Record Test)
# replayed in the real `paraview` client, with image baselines under Testing/Data/Baseline/.
# Needs an X server: run ctest under xvfb-run, as for the other GL tests.
#
# This file is used twice:
#  - included from Testing/CMakeLists.txt, it adds one CTest test per script;
#  - run as `cmake -P GUI.cmake -D...` (CMAKE_SCRIPT_MODE_FILE set), it is the test driver: it
#    empties the test directory, runs the client, prints its output and fails when the client
#    failed or when fewer strict image checks passed than the script calls (a Python error in the
#    shell is otherwise silent).
#
# Intermediate image checks in ParaView 5.11 (pqXMLEventSource): a <pqcompareview object="VIEW"
# baseline="..." width= height= threshold= /> element captures the view at width x height and
# compares it with vtkTesting. A failure only logs "ERROR: The following event FAILED !!! Yet will
# continue with the rest of the test." and the client still exits 0, hence the
# FAIL_REGULAR_EXPRESSION below. The baseline path takes $PARAVIEW_TEST_BASELINE_DIR
# (--baseline-directory), the test image is written to --test-directory, which must exist.
# vtkTesting forgives per-channel differences below 105, so the scripts also run the strict check
# of XML/PsiGUICheck.py through the Python shell (see that file).

if (CMAKE_SCRIPT_MODE_FILE)
  # --- driver -------------------------------------------------------------------------------
  file(REMOVE_RECURSE "${TEST_DIR}")
  file(MAKE_DIRECTORY "${TEST_DIR}")
  file(READ "${SCRIPT}" _script)
  # ParaView 5.13 and later ask neither before volume rendering this unstructured grid nor before
  # Edit > Delete All: the events that answer those prompts (pqCoreUtilities::promptUser) are
  # played only where the prompts exist, from a copy of the script without them.
  if (PARAVIEW_VERSION VERSION_GREATER_EQUAL "5.13")
    string(REGEX REPLACE "[^\n]*CoreUtilitiesPromptUser[^\n]*\n" "" _script "${_script}")
    get_filename_component(_name "${SCRIPT}" NAME)
    set(SCRIPT "${TEST_DIR}/${_name}")
    file(WRITE "${SCRIPT}" "${_script}")
  endif ()
  # the strict checks the script calls: <pqevent ... arguments="psi['check'](...)" /> and
  # psi['check_interaction'](...), psi['check_report']() and psi['check_readout'](...)
  string(REGEX MATCHALL "arguments=\"psi\\['check(_interaction|_report|_readout)?'\\]" _calls "${_script}")
  list(LENGTH _calls _expected)
  # a script whose checks are all its own has no final image to compare (BASELINE empty)
  set(_final)
  if (BASELINE)
    set(_final "--test-baseline=${BASELINE}" --test-threshold=5)
  endif ()
  execute_process(
    COMMAND "${PARAVIEW}" --dr
            "--plugin-search-paths=${PLUGIN_DIR}"
            --plugins=PsiVolume
            "--test-script=${SCRIPT}"
            ${_final}
            "--test-directory=${TEST_DIR}"
            "--baseline-directory=${BASELINE_DIR}"
            "--data-directory=${DATA_DIR}"
            --exit
    # below the CTest TIMEOUT, so that a client stuck in a dialog is killed, not left running
    TIMEOUT 100
    RESULT_VARIABLE _rc
    OUTPUT_VARIABLE _out
    ERROR_VARIABLE _out
    ECHO_OUTPUT_VARIABLE
    ECHO_ERROR_VARIABLE)
  string(REGEX MATCHALL "PsiGUICheck passed:" _passed "${_out}")
  list(LENGTH _passed _npassed)
  message("PsiGUI driver: client exit code ${_rc}; ${_npassed} of ${_expected} strict image checks passed")
  if (NOT _rc EQUAL 0 OR NOT _npassed EQUAL _expected)
    message(FATAL_ERROR "PsiGUI driver: test failed")
  endif ()
  return ()
endif ()

# ParaView's own paraview_add_client_tests (Testing/PanelGUI.cmake uses it) cannot count the
# strict checks a script calls (a Python error in the shell is otherwise silent) nor play a
# script without the prompts only ParaView 5.11 asks, so these tests keep the driver above.
find_program(PARAVIEW_CLIENT_EXECUTABLE NAMES paraview)
if (NOT PARAVIEW_CLIENT_EXECUTABLE)
  message(STATUS "paraview client not found: GUI tests disabled")
  return ()
endif ()

# Each script's steps are compared with Data/Baseline/<name>_<step>.png or <name>.png, and the
# client compares the final view with <name>_baseline below (--test-baseline; a failure there
# makes the client exit 1).
#   PsiVolumeGUI: integration methods, isosurfaces, state save/load (see XML/PsiVolumeGUI.xml).
#   PsiVolumeGUIOpacityState: the opacity unit distance typed in the 'Psi Volume Opacity' group
#     survives state save/load (see the XML file's header).
#   PsiVolumeGUIOpenFile: File > Open of a tetrahedral .off file (the plugin's reader), rendered
#     with 'Psi Volume'.
#   PsiVolumeGUIInteraction: a recorded drag in the view, drawn by the volume level of detail
#     ('Volume LOD') and by the full frame ('Full frame'), as the read-out says; no final image.
#   PsiVolumeGUIAccuracyReport: Tools > Accuracy report (the plugin's action) on a small mesh;
#     the table it shows names every row of the report; no final image.
#   PsiVolumeGUIIntermixedState: two 'Psi Volume' displays in one view (drawn intermixed) give the
#     image of their union drawn as one volume, and the same in the other show order and after
#     state save/load; each step is compared with the script's own first image (no baseline
#     file, no final image).
set(psi_gui_tests PsiVolumeGUI PsiVolumeGUIOpacityState PsiVolumeGUIOpenFile
  PsiVolumeGUIInteraction PsiVolumeGUIAccuracyReport PsiVolumeGUIIntermixedState)
set(PsiVolumeGUIOpenFile_baseline PsiVolumeGUIOpenFile.png)
set(PsiVolumeGUI_baseline PsiVolumeGUI.png)
set(PsiVolumeGUIOpacityState_baseline PsiVolumeGUI_Average.png)
# ParaView 6 draws the same scene on its own default background and color map (its settings
# changed both), so its images have their own baselines.
set(psi_gui_baselines "${CMAKE_CURRENT_SOURCE_DIR}/Data/Baseline")
if (ParaView_VERSION VERSION_GREATER_EQUAL "6.0")
  set(psi_gui_baselines "${CMAKE_CURRENT_SOURCE_DIR}/Data/Baseline/pv6")
endif ()
foreach (name IN LISTS psi_gui_tests)
  add_test(NAME PsiGUI.${name}
    COMMAND "${CMAKE_COMMAND}"
            "-DPARAVIEW=${PARAVIEW_CLIENT_EXECUTABLE}"
            "-DPARAVIEW_VERSION=${ParaView_VERSION}"
            "-DPLUGIN_DIR=$<TARGET_FILE_DIR:PsiVolume>"
            "-DSCRIPT=${CMAKE_CURRENT_SOURCE_DIR}/XML/${name}.xml"
            "-DBASELINE=$<$<BOOL:${${name}_baseline}>:${psi_gui_baselines}/${${name}_baseline}>"
            "-DBASELINE_DIR=${psi_gui_baselines}"
            "-DDATA_DIR=${CMAKE_CURRENT_SOURCE_DIR}"
            "-DTEST_DIR=${CMAKE_BINARY_DIR}/Testing/Temporary/GUI/${name}"
            -P "${CMAKE_CURRENT_LIST_FILE}")
  set_tests_properties(PsiGUI.${name} PROPERTIES
    LABELS "GUI"
    # the strict check (XML/PsiGUICheck.py) writes its image with the project's Python package
    ENVIRONMENT "${PSI_PYTHONPATH}"
    TIMEOUT 120
    # "Couldn't find object": a widget path does not exist in this ParaView version;
    # "Failed to parse": bad XML; "The following event FAILED": an intermediate <pqcompareview>
    # (or <pqcompareimage>) did not match its baseline; "PsiGUICheck FAILED": the strict check;
    # "Unhandled error": any other event QtTesting could not play.
    FAIL_REGULAR_EXPRESSION "Couldn't find object|Failed to parse|The following event FAILED|PsiGUICheck FAILED|Unhandled error"
    RESOURCE_LOCK PsiGUI)
endforeach ()
# The accuracy report finds its reference renderer beside the plugin loaded; named here, it is a
# target of the test (scripts/mutation_test.py builds the targets a test's environment names).
set_tests_properties(PsiGUI.PsiVolumeGUIAccuracyReport PROPERTIES
  ENVIRONMENT "${PSI_PYTHONPATH};PSI_TEST_REFERENCE=$<TARGET_FILE:psi_reference_render>")
