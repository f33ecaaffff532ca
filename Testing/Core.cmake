# Tests of the Core module (GL-free math), included from Testing/CMakeLists.txt. A test of Core
# code links PsiVolume::Core (with PsiReference for the exact references, and VTK's own modules
# for the data it builds), not the Representations module or ParaView's rendering libraries.

# The PTINT truth table and its fan, Psi and the segment integrals against an independent
# quadrature, the Psi table.
add_executable(TestPsiMath Cxx/TestPsiMath.cxx)
target_link_libraries(TestPsiMath PRIVATE PsiVolume::Core PsiReference)
add_test(NAME PsiCore.Math COMMAND TestPsiMath)

# Every integration method against the reference of its model; the panel's IntegrationMethod
# enumeration checked against psi::IntegrationMethodTable().
add_executable(TestIntegrationMethods Cxx/TestIntegrationMethods.cxx)
target_link_libraries(TestIntegrationMethods PRIVATE PsiVolume::Core PsiReference
  ParaView::VTKExtensionsCore)
target_compile_definitions(TestIntegrationMethods PRIVATE
  PSI_REPRESENTATION_XML="${PROJECT_SOURCE_DIR}/XML/PsiVolumeRepresentation.xml")
add_test(NAME PsiCore.IntegrationMethods COMMAND TestIntegrationMethods
  "${PROJECT_SOURCE_DIR}/XML/PsiVolumeRepresentation.xml")

# Exact adaptive sampling: the transfer function's nodes, 'Auto', the early-discard prefix.
add_executable(TestTransferFunctionNodes Cxx/TestTransferFunctionNodes.cxx)
target_link_libraries(TestTransferFunctionNodes PRIVATE PsiVolume::Core PsiReference
  VTK::RenderingCore)
add_test(NAME PsiCore.TransferFunctionNodes COMMAND TestTransferFunctionNodes)

add_executable(TestPixelRays Cxx/TestPixelRays.cxx)
target_link_libraries(TestPixelRays PRIVATE PsiVolume::Core PsiReference VTK::RenderingCore)
add_test(NAME PsiCore.PixelRays COMMAND TestPixelRays)

# The renderer's mesh gathering and its reuse of the filter's FaceNeighbors.
add_executable(TestTetMesh Cxx/TestTetMesh.cxx)
target_link_libraries(TestTetMesh PRIVATE PsiVolume::Filters PsiVolume::Core VTK::CommonCore
  VTK::CommonDataModel VTK::CommonExecutionModel VTK::RenderingCore)
add_test(NAME PsiCore.TetMesh COMMAND TestTetMesh)

# Several volumes as one mesh: placement, slot scalars, the concatenated tables, neighbours.
add_executable(TestIntermixedMesh Cxx/TestIntermixedMesh.cxx)
target_link_libraries(TestIntermixedMesh PRIVATE PsiVolume::Core VTK::CommonCore
  VTK::CommonDataModel VTK::RenderingCore)
add_test(NAME PsiCore.IntermixedMesh COMMAND TestIntermixedMesh)

# MPVONC's order against CGAL's exact orientation from many views.
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL REQUIRED)
add_executable(TestMPVONC Cxx/TestMPVONC.cxx)
target_link_libraries(TestMPVONC PRIVATE PsiVolume::Filters PsiVolume::Core CGAL::CGAL
  VTK::CommonCore VTK::CommonDataModel VTK::CommonExecutionModel)
add_test(NAME PsiCore.MPVONC COMMAND TestMPVONC)

# The one settings type: the representation's XML defaults and ranges against it, the clamp and
# its warning, each 'Auto'.
add_executable(TestSettings Cxx/TestSettings.cxx)
target_link_libraries(TestSettings PRIVATE PsiVolume::Core ParaView::VTKExtensionsCore)
add_test(NAME PsiCore.Settings COMMAND TestSettings
  "${PROJECT_SOURCE_DIR}/XML/PsiVolumeRepresentation.xml")

# The frame plan: each effect and table exactly when the scene calls for it (GL-free).
add_executable(TestFramePlan Cxx/TestFramePlan.cxx)
target_link_libraries(TestFramePlan PRIVATE PsiVolume::Core)
add_test(NAME PsiCore.FramePlan COMMAND TestFramePlan)

# The choice among equal ways of drawing a frame by timing them (GL-free, given times).
add_executable(TestMeasuredChoice Cxx/TestMeasuredChoice.cxx)
target_link_libraries(TestMeasuredChoice PRIVATE PsiVolume::Core)
add_test(NAME PsiCore.MeasuredChoice COMMAND TestMeasuredChoice)

# The exact reference of several media sharing space against what it reduces to.
add_executable(TestReferenceMedia Cxx/TestReferenceMedia.cxx)
target_link_libraries(TestReferenceMedia PRIVATE PsiVolume::Core PsiReference VTK::RenderingCore
  VTK::FiltersGeneral VTK::FiltersSources VTK::ImagingCore)
add_test(NAME PsiCore.ReferenceMedia COMMAND TestReferenceMedia)
