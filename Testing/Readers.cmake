# Tests of the tetrahedral OFF reader, the bad-input and MPI pvpython tests, and the fuzzer.
# Included from Testing/CMakeLists.txt.

# --- C++ reader test (always).
add_executable(TestOFFReader Cxx/TestOFFReader.cxx)
target_link_libraries(TestOFFReader PRIVATE PsiVolume::Readers VTK::CommonCore
  VTK::CommonDataModel VTK::CommonExecutionModel)
file(MAKE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/OFFReaderTemp")
add_test(NAME OFFReader COMMAND TestOFFReader "${CMAKE_CURRENT_BINARY_DIR}/OFFReaderTemp")
set_tests_properties(OFFReader PROPERTIES TIMEOUT 60)

# --- libFuzzer target (clang only, -DPSI_BUILD_FUZZERS=ON). The reader library is instrumented
# in Readers/CMakeLists.txt. The CTest run fuzzes for 30 s from the seeds in Fuzz/corpus/, writing
# new inputs to a corpus in the build tree (never to the source tree).
option(PSI_BUILD_FUZZERS "Build the libFuzzer targets (needs clang)" OFF)
if (PSI_BUILD_FUZZERS)
  if (NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(WARNING "PSI_BUILD_FUZZERS needs clang (configure with -DCMAKE_CXX_COMPILER=clang++ "
      "-DCMAKE_C_COMPILER=clang): the fuzzers are not built.")
  else ()
    set(_psi_fuzz_flags -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
      -fno-omit-frame-pointer -g)
    add_executable(fuzz_off_reader Fuzz/fuzz_off_reader.cxx)
    target_compile_options(fuzz_off_reader PRIVATE ${_psi_fuzz_flags})
    target_link_options(fuzz_off_reader PRIVATE ${_psi_fuzz_flags})
    target_link_libraries(fuzz_off_reader PRIVATE PsiVolume::Readers VTK::CommonCore
      VTK::CommonDataModel VTK::CommonExecutionModel)
    set(_psi_fuzz_work "${CMAKE_CURRENT_BINARY_DIR}/fuzz_off_reader")
    file(MAKE_DIRECTORY "${_psi_fuzz_work}/corpus" "${_psi_fuzz_work}/artifacts")
    add_test(NAME Fuzz.OFFReader
      COMMAND fuzz_off_reader -max_total_time=30 -timeout=10 -rss_limit_mb=2048
              -print_final_stats=1 "-dict=${CMAKE_CURRENT_SOURCE_DIR}/Fuzz/off.dict"
              "-artifact_prefix=${_psi_fuzz_work}/artifacts/"
              "${_psi_fuzz_work}/corpus" "${CMAKE_CURRENT_SOURCE_DIR}/Fuzz/corpus")
    # VTK's singletons are alive at exit: only leaks inside an input's run count.
    set_tests_properties(Fuzz.OFFReader PROPERTIES TIMEOUT 120
      ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1")
  endif ()
endif ()

# --- pvpython tests: bad input to 'Psi Volume' (and to the reader) and MPI ordered compositing.
find_program(PVPYTHON_EXECUTABLE NAMES pvpython REQUIRED)
# One test per case, each in its own pvpython, so that a crash or a hang names its case.
set(psi_bad_input_cases nontet surface cellscalars nonfinite empty degenerate quadratic multiblock
  large reader unitdistance outofrange)
foreach (case IN LISTS psi_bad_input_cases)
  add_test(NAME PsiPython.bad_input.${case}
    COMMAND "${PVPYTHON_EXECUTABLE}" --force-offscreen-rendering
            "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_bad_input.py" ${case})
  set_tests_properties(PsiPython.bad_input.${case} PROPERTIES
    ENVIRONMENT "PSI_PLUGIN=$<TARGET_FILE:PsiVolume>;PSI_DATA_DIR=${PSI_DATA_DIR}"
    SKIP_RETURN_CODE 77
    TIMEOUT 240)
endforeach ()
# More than one draw call (5.1M tetrahedra, ~15-20 s here): run alone, it is the heaviest.
set_tests_properties(PsiPython.bad_input.large PROPERTIES RUN_SERIAL ON)

find_program(PVBATCH_EXECUTABLE NAMES pvbatch)
find_program(MPIEXEC_EXECUTABLE NAMES mpiexec mpirun)
if (PVBATCH_EXECUTABLE AND MPIEXEC_EXECUTABLE)
  add_test(NAME PsiPython.mpi
    COMMAND "${MPIEXEC_EXECUTABLE}" --allow-run-as-root -n 2 "${PVBATCH_EXECUTABLE}"
            --force-offscreen-rendering "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_mpi.py")
  set_tests_properties(PsiPython.mpi PROPERTIES
    ENVIRONMENT "PSI_PLUGIN=$<TARGET_FILE:PsiVolume>;PSI_PVBATCH=${PVBATCH_EXECUTABLE};OMPI_MCA_rmaps_base_oversubscribe=1"
    SKIP_RETURN_CODE 77
    TIMEOUT 240
    RUN_SERIAL ON)
else ()
  message(STATUS "pvbatch or mpiexec not found: PsiPython.mpi is not registered")
endif ()
