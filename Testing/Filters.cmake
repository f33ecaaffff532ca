# Tests of the Filters module and of MPVONC, included from Testing/CMakeLists.txt.
# Tests that read the shared data exit with 77 when it is absent: reported as skipped, not passed.
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL REQUIRED)

add_executable(TestConformingTetrahedralize Cxx/TestConformingTetrahedralize.cxx)
target_link_libraries(TestConformingTetrahedralize PRIVATE PsiVolume::Filters
  PsiVolume::Representations CGAL::CGAL VTK::CommonCore VTK::CommonDataModel
  VTK::CommonExecutionModel VTK::IOLegacy VTK::IOParallel)
add_test(NAME ConformingTetrahedralize COMMAND TestConformingTetrahedralize synthetic)
add_test(NAME ConformingTetrahedralizeBluntFin
  COMMAND TestConformingTetrahedralize bluntfin "${PSI_DATA_DIR}")
add_test(NAME ConformingTetrahedralizeBadInput
  COMMAND TestConformingTetrahedralize badinput "${PSI_DATA_DIR}")
set_tests_properties(ConformingTetrahedralizeBluntFin ConformingTetrahedralizeBadInput
  PROPERTIES SKIP_RETURN_CODE 77)

add_executable(TestMPVONC Cxx/TestMPVONC.cxx)
target_link_libraries(TestMPVONC PRIVATE PsiVolume::Filters PsiVolume::Representations PsiTestSupport
  CGAL::CGAL VTK::CommonCore VTK::CommonDataModel VTK::CommonExecutionModel)
add_test(NAME MPVONC COMMAND TestMPVONC)

# The renderer's mesh gathering and its reuse of the filter's FaceNeighbors (GL-free).
add_executable(TestTetMesh Cxx/TestTetMesh.cxx)
target_link_libraries(TestTetMesh PRIVATE PsiVolume::Filters PsiVolume::Core VTK::CommonCore
  VTK::CommonDataModel VTK::CommonExecutionModel VTK::RenderingCore)
add_test(NAME TetMesh COMMAND TestTetMesh)
