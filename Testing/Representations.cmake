# Tests of the Representations module (the ParaView representation, its interaction and level
# of detail), included from Testing/CMakeLists.txt; the representation inside ParaView is tested
# by the pvpython tests (Python.cmake).

# The interactive level of detail's image: which lattice points it hides (GL-free).
add_executable(TestLODImage Cxx/TestLODImage.cxx)
target_link_libraries(TestLODImage PRIVATE PsiVolume::Representations VTK::FiltersCore
  VTK::CommonDataModel)
add_test(NAME PsiRepresentations.LODImage COMMAND TestLODImage)

# The order in which several displays' levels of detail are drawn: back to front by their boxes.
add_executable(TestLODFrames Cxx/TestLODFrames.cxx)
target_link_libraries(TestLODFrames PRIVATE PsiVolume::Representations VTK::RenderingCore)
add_test(NAME PsiRepresentations.LODFrames COMMAND TestLODFrames)
