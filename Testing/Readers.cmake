# Tests of the Readers module (the tetrahedral OFF reader) and its fuzzer, included from
# Testing/CMakeLists.txt. The reader inside ParaView is tested by PsiPython.bad_input.reader.

# --- C++ reader test (always).
add_executable(TestOFFReader Cxx/TestOFFReader.cxx)
target_link_libraries(TestOFFReader PRIVATE PsiVolume::Readers VTK::CommonCore
  VTK::CommonDataModel VTK::CommonExecutionModel)
file(MAKE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/OFFReaderTemp")
add_test(NAME PsiReaders.OFFReader COMMAND TestOFFReader "${CMAKE_CURRENT_BINARY_DIR}/OFFReaderTemp")
set_tests_properties(PsiReaders.OFFReader PROPERTIES TIMEOUT 60)

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
    add_test(NAME PsiReaders.Fuzz
      COMMAND fuzz_off_reader -max_total_time=30 -timeout=10 -rss_limit_mb=2048
              -print_final_stats=1 "-dict=${CMAKE_CURRENT_SOURCE_DIR}/Fuzz/off.dict"
              "-artifact_prefix=${_psi_fuzz_work}/artifacts/"
              "${_psi_fuzz_work}/corpus" "${CMAKE_CURRENT_SOURCE_DIR}/Fuzz/corpus")
    # VTK's singletons are alive at exit: only leaks inside an input's run count.
    set_tests_properties(PsiReaders.Fuzz PROPERTIES TIMEOUT 120
      ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1")
  endif ()
endif ()
