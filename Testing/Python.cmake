# The plugin inside ParaView: pvpython tests (PsiPython.*), included from Testing/CMakeLists.txt
# (psi_add_python_test is defined there). They need an X server too.

# Properties, parity with 'Volume', coloring, mixed cells, narrow spikes, the benchmark's
# reference, separate opacity, translucent geometry, the timing harness (GL-free).
psi_add_python_test(plugin_basics)
foreach (name IN ITEMS properties render_command vector_coloring mixed_cells
    narrow_spikes isosurface_coverage benchmark_reference parity separate_opacity
    translucent_geometry timing)
  psi_add_python_test(${name})
endforeach ()
# The separate opacity array and translucent geometry with the compute projector too.
foreach (name IN ITEMS separate_opacity translucent_geometry)
  psi_add_python_test(${name}.compute SCRIPT ${name} ARGS --projector compute)
endforeach ()

psi_add_python_test(isosurfaces
  ENVIRONMENT "PSI_TEST_OUTPUT=${CMAKE_BINARY_DIR}/Testing/Images")

# The accuracy report (psivolume.accuracy) on a small scene: outputs, one row per method,
# finite errors, the reference against itself, the 'Resample To Image' and interactive rows (at
# small resampling sizes); the timeout allows for a loaded machine (it starts child pvpythons).
psi_add_python_test(accuracy_report TIMEOUT 600
  ENVIRONMENT "PSI_REFERENCE_RENDER=$<TARGET_FILE:psi_reference_render>")
# The report on the user's scene, one case each: the scene left as found (also when the report
# fails), arrays of any name, a cell array sharing its name with a point array, and a failure of
# the reference renderer said in one line.
foreach (case IN ITEMS settings names cells failure volumes)
  psi_add_python_test(report_scene.${case} SCRIPT report_scene ARGS ${case} TIMEOUT 300
    ENVIRONMENT "PSI_REFERENCE_RENDER=$<TARGET_FILE:psi_reference_render>")
endforeach ()

# Constant fields and scalar ranges that float cannot hold (denormal widths, far from 0):
# against 'Projected tetra' and the reference, and each path's image invariant under scaling.
psi_add_python_test(scalar_ranges TIMEOUT 300
  ENVIRONMENT "PSI_REFERENCE_RENDER=$<TARGET_FILE:psi_reference_render>")

# Bad input to 'Psi Volume' (and to the reader): one test per case, each in its own pvpython,
# so that a crash or a hang names its case.
foreach (case IN ITEMS nontet surface cellscalars nonfinite empty degenerate quadratic multiblock
    large reader unitdistance outofrange)
  psi_add_python_test(bad_input.${case} SCRIPT bad_input ARGS ${case} TIMEOUT 240)
endforeach ()
# More than one draw call (5.1M tetrahedra, ~15-20 s here): run alone, it is the heaviest.
set_tests_properties(PsiPython.bad_input.large PROPERTIES RUN_SERIAL ON)

# MPI ordered compositing: 2 pvbatch ranks against a serial render, the still frame (mpi), the
# interactive level of detail (mpi_lod) and two displays intermixed, in either show order
# (mpi_intermixed). Under the MPI watchdog (PSI_MPI_WATCHDOG_COMMAND,
# Testing/CMakeLists.txt): a hang ends with each rank's stacks, well before CTest's timeout.
if (PVBATCH_EXECUTABLE AND MPIEXEC_EXECUTABLE)
  set(environment "PSI_PVBATCH=${PVBATCH_EXECUTABLE}" "OMPI_MCA_rmaps_base_oversubscribe=1"
    "PSI_DATA_DIR=${PSI_DATA_DIR}")
  foreach (name IN ITEMS mpi mpi_lod mpi_intermixed)
    set(command ${PSI_MPI_WATCHDOG_COMMAND} "${MPIEXEC_EXECUTABLE}" --allow-run-as-root -n 2
      "${PVBATCH_EXECUTABLE}" --force-offscreen-rendering
      "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_${name}.py")
    add_test(NAME PsiPython.${name} COMMAND ${command})
    set_tests_properties(PsiPython.${name} PROPERTIES
      ENVIRONMENT "PSI_PLUGIN=$<TARGET_FILE:PsiVolume>;${PSI_PYTHONPATH};${environment}"
      SKIP_RETURN_CODE 77
      TIMEOUT ${PSI_MPI_TEST_TIMEOUT})
    set_tests_properties(PsiPython.${name} PROPERTIES RUN_SERIAL ON)
    if (name STREQUAL "mpi") # the ranks load the installed plugin (what an install changes)
      psi_add_installed_test(${name} TIMEOUT ${PSI_MPI_TEST_TIMEOUT} ENVIRONMENT ${environment}
        COMMAND ${command})
      set_tests_properties(PsiInstalled.${name} PROPERTIES RUN_SERIAL ON)
    endif ()
  endforeach ()
else ()
  message(STATUS "pvbatch or mpiexec not found: PsiPython.mpi, .mpi_lod and .mpi_intermixed are not registered")
endif ()

# Client-server: a pvpython client renders through `mpiexec -n 2 pvserver` (remote rendering,
# ordered compositing on the server) and compares with a serial render. The client runs under
# the MPI watchdog, whose stacks then cover the client and the server's ranks it started.
if (PVSERVER_EXECUTABLE AND MPIEXEC_EXECUTABLE)
  psi_add_python_test(pvserver MPI_WATCHDOG INSTALLED
    ENVIRONMENT "PSI_PVSERVER=${PVSERVER_EXECUTABLE};PSI_MPIEXEC=${MPIEXEC_EXECUTABLE};OMPI_MCA_rmaps_base_oversubscribe=1")
  set_tests_properties(PsiPython.pvserver PsiInstalled.pvserver PROPERTIES RUN_SERIAL ON)
else ()
  message(STATUS "pvserver or mpiexec not found: PsiPython.pvserver is not registered")
endif ()

# While the camera moves: the volume level of detail chosen by mode and budget, never in still
# renders or screenshots, close to the full frame, hard inputs, a state file (part `modes`); rebuilt
# for new arrays and data (`changes`) and time steps (`time`).
foreach (part IN ITEMS modes changes time)
  psi_add_python_test(interaction.${part} SCRIPT interaction ARGS ${part} TIMEOUT 300)
endforeach ()

# Several 'Psi Volume' displays in one view, intermixed: either show order the same image, their
# own arrays and maps, one hidden or deleted, a state file.
psi_add_python_test(intermixed TIMEOUT 300)

# Scenes nobody wrote by hand: a fixed set of seeds of the randomized scene checker (meshes,
# arrays, transfer functions, cameras and settings drawn at random, each still frame against the
# exact reference, the interactive frame against the still one). `--seeds N` runs more. Seeds
# 0-39 in three parts (one scene in two carries further volumes, whose combined draw compiles
# its own shader programs: 40 seeds in one process took 114 s).
foreach (first IN ITEMS 0 14 27)
  set(seeds 13)
  if (first EQUAL 0)
    set(seeds 14)
  endif ()
  psi_add_python_test(random_scenes.${first} SCRIPT random_scenes ARGS --first ${first}
    --seeds ${seeds} TIMEOUT 600
    ENVIRONMENT "PSI_REFERENCE_RENDER=$<TARGET_FILE:psi_reference_render>")
endforeach ()

# The level of detail on common real inputs, against the still frame: built in the first
# interactive render, one name for a point and a cell array, array and component switches, a
# thin slab, a representation deleted and replaced.
psi_add_python_test(lod_inputs TIMEOUT 300)

# The level of detail of several displays in one view: drawn back to front together, the same in
# either show order and close to the intermixed still frame, chosen by 'Auto' for every display.
psi_add_python_test(lod_several TIMEOUT 300)

# The accuracy report as the GUI runs it (psivolume.gui), after `import psivolume` by the
# package's name once the plugin is loaded: no PYTHONPATH and no path given (the report finds
# the plugin ParaView loaded, and its reference renderer beside the build's).
add_test(NAME PsiPython.gui_report
  COMMAND "${PVPYTHON_EXECUTABLE}" --force-offscreen-rendering
          "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_gui_report.py"
          --package-dir "${PROJECT_SOURCE_DIR}/Python")
# (the plugin to load, and the reference renderer the report must find, in variables of their
# own, which the report does not read)
set_tests_properties(PsiPython.gui_report PROPERTIES
  ENVIRONMENT "PSI_TEST_PLUGIN=$<TARGET_FILE:PsiVolume>;PSI_TEST_REFERENCE=$<TARGET_FILE:psi_reference_render>;PYTHONPATH="
  TIMEOUT 120)

# The install tree: `cmake --install` into a temporary prefix, then pvpython loads the plugin from
# it by path, draws the embedded default with 'Psi Volume' and imports psivolume from it, with the
# checkout's Python/ off its path (Testing/Install/run_installed.py).
add_test(NAME PsiPython.installed
  COMMAND "${PSI_PYTHON3}" "${CMAKE_CURRENT_SOURCE_DIR}/Install/run_installed.py"
          --build "${CMAKE_BINARY_DIR}" --cmake "${CMAKE_COMMAND}" --pvpython "${PVPYTHON_EXECUTABLE}"
          --plugins-dir "${PSI_PLUGINS_DIR}" --python-dir "${PSI_PYTHON_DESTINATION}")
set_tests_properties(PsiPython.installed PROPERTIES TIMEOUT 300)
