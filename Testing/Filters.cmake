# Tests of the Filters module (the CGAL conforming tetrahedralization), included from
# Testing/CMakeLists.txt (after Core.cmake, which finds CGAL).
add_executable(TestConformingTetrahedralize Cxx/TestConformingTetrahedralize.cxx)
target_link_libraries(TestConformingTetrahedralize PRIVATE PsiVolume::Filters CGAL::CGAL
  VTK::CommonCore VTK::CommonDataModel VTK::CommonExecutionModel VTK::IOLegacy VTK::IOParallel)
add_test(NAME PsiFilters.ConformingTetrahedralize
  COMMAND TestConformingTetrahedralize synthetic)
add_test(NAME PsiFilters.ConformingTetrahedralize.BluntFin
  COMMAND TestConformingTetrahedralize bluntfin "${PSI_DATA_DIR}")
add_test(NAME PsiFilters.ConformingTetrahedralize.BadInput
  COMMAND TestConformingTetrahedralize badinput "${PSI_DATA_DIR}")
set_tests_properties(PsiFilters.ConformingTetrahedralize.BluntFin
  PsiFilters.ConformingTetrahedralize.BadInput PROPERTIES SKIP_RETURN_CODE 77)
