# Isosurfaces and adaptive transfer-function sampling, included from
# Testing/CMakeLists.txt. GL tests need an X server (run ctest under xvfb-run).
add_executable(TestPsiIsosurfaces Cxx/TestPsiIsosurfaces.cxx)
target_link_libraries(TestPsiIsosurfaces PRIVATE PsiVolume::Representations PsiTestSupport
  VTK::RenderingOpenGL2 VTK::FiltersGeneral VTK::FiltersSources VTK::ImagingCore VTK::IOImage
  VTK::RenderingCore)
vtk_module_autoinit(TARGETS TestPsiIsosurfaces MODULES VTK::RenderingOpenGL2)
file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/Testing/Images")
psi_add_render_test(PsiIsosurfaces TestPsiIsosurfaces FAN)

find_program(PVPYTHON_EXECUTABLE NAMES pvpython REQUIRED)
add_test(NAME PsiPython.isosurfaces
  COMMAND "${PVPYTHON_EXECUTABLE}" --force-offscreen-rendering
          "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_isosurfaces.py")
set_tests_properties(PsiPython.isosurfaces PROPERTIES
  ENVIRONMENT "PSI_PLUGIN=$<TARGET_FILE:PsiVolume>;PSI_TEST_OUTPUT=${CMAKE_BINARY_DIR}/Testing/Images"
  SKIP_RETURN_CODE 77
  TIMEOUT 600)

# Degenerate projections (truth-table classes 3 and 4, exact in float) and the drawn visibility
# order, both against exact references (PsiReferenceRaycaster; ray/tetrahedron intersection).
add_executable(TestPsiDegenerateProjections Cxx/TestPsiDegenerateProjections.cxx)
target_link_libraries(TestPsiDegenerateProjections PRIVATE PsiVolume::Representations PsiTestSupport
  VTK::RenderingOpenGL2 VTK::FiltersGeneral VTK::ImagingCore VTK::IOImage VTK::RenderingCore)
vtk_module_autoinit(TARGETS TestPsiDegenerateProjections MODULES VTK::RenderingOpenGL2)
psi_add_render_test(PsiDegenerateProjections TestPsiDegenerateProjections FAN TIMEOUT 120)

add_executable(TestPsiVisibilityOrder Cxx/TestPsiVisibilityOrder.cxx)
target_link_libraries(TestPsiVisibilityOrder PRIVATE PsiVolume::Representations PsiVolume::Core PsiTestSupport
  VTK::RenderingOpenGL2 VTK::FiltersGeneral VTK::RenderingCore)
vtk_module_autoinit(TARGETS TestPsiVisibilityOrder MODULES VTK::RenderingOpenGL2)
add_test(NAME PsiVisibilityOrder COMMAND TestPsiVisibilityOrder)
set_tests_properties(PsiVisibilityOrder PROPERTIES TIMEOUT 120)

# Translucent geometry intermixed with the volume through VTK's dual depth peeling, against the
# reference ray caster compositing the surfaces' layers.
add_executable(TestPsiTranslucentGeometry Cxx/TestPsiTranslucentGeometry.cxx)
target_link_libraries(TestPsiTranslucentGeometry PRIVATE PsiVolume::Representations
  PsiTestSupport VTK::RenderingOpenGL2 VTK::FiltersSources VTK::ImagingCore VTK::IOImage
  VTK::RenderingCore)
vtk_module_autoinit(TARGETS TestPsiTranslucentGeometry MODULES VTK::RenderingOpenGL2)
psi_add_render_test(PsiTranslucentGeometry TestPsiTranslucentGeometry TIMEOUT 300)
