# Tests of the Rendering module (the OpenGL mapper and its parts, on VTK alone), included from
# Testing/CMakeLists.txt. GL tests need an X server.

# Every render test runs once per projector (psi::Projectors), set on the mapper from the
# command line (the test checks that the frames used it), and with FAN also drawn with Shirley
# and Tuchman's fan instead of the default silhouettes. The geometry-shader run writes images.
# With PARTS, each run is split into one test per part (the executable's --part NAME), named
# <test>[.compute|.fan].<part>: a part compiles its own shader programs, which is most of a
# render test's time on Mesa's llvmpipe with an empty shader cache.
function(psi_add_render_test name executable)
  cmake_parse_arguments(arg "FAN" "TIMEOUT" "PARTS" ${ARGN})
  set(runs geometry compute)
  if (arg_FAN)
    list(APPEND runs fan)
  endif ()
  set(parts whole)
  if (arg_PARTS)
    set(parts ${arg_PARTS})
  endif ()
  set(variants)
  foreach (run IN LISTS runs)
    set(test PsiRendering.${name})
    if (run STREQUAL "geometry") # the geometry-shader run writes images
      set(options "${CMAKE_BINARY_DIR}/Testing/Images" --projector geometry)
    elseif (run STREQUAL "compute")
      set(test ${test}.compute)
      set(options --projector compute)
    else ()
      set(test ${test}.fan)
      set(options --decomposition fan)
    endif ()
    foreach (part IN LISTS parts)
      if (part STREQUAL "whole")
        add_test(NAME ${test} COMMAND ${executable} ${options})
        list(APPEND variants ${test})
      else ()
        add_test(NAME ${test}.${part} COMMAND ${executable} ${options} --part ${part})
        list(APPEND variants ${test}.${part})
      endif ()
    endforeach ()
  endforeach ()
  if (arg_TIMEOUT)
    set_tests_properties(${variants} PROPERTIES TIMEOUT ${arg_TIMEOUT})
  endif ()
endfunction ()

# A GL test executable of this module.
function(psi_add_gl_executable name)
  add_executable(${name} Cxx/${name}.cxx)
  target_link_libraries(${name} PRIVATE PsiVolume::Rendering PsiVolume::Core PsiReference
    VTK::RenderingOpenGL2 VTK::FiltersGeneral VTK::FiltersSources VTK::ImagingCore VTK::IOImage
    VTK::RenderingCore ${ARGN})
  vtk_module_autoinit(TARGETS ${name} MODULES VTK::RenderingOpenGL2)
endfunction ()

# Images against the exact reference (PsiReferenceRaycaster): perspective, parallel, camera
# inside, opaque geometry, each method.
psi_add_gl_executable(TestPsiVolumeRender)
psi_add_render_test(VolumeRender TestPsiVolumeRender FAN)

# Isosurfaces and adaptive transfer-function sampling.
psi_add_gl_executable(TestPsiIsosurfaces)
psi_add_render_test(Isosurfaces TestPsiIsosurfaces FAN PARTS view0 view1 view2 view3 others)

# Degenerate projections (truth-table classes 3 and 4, exact in float) and the drawn visibility
# order, both against exact references (PsiReferenceRaycaster; ray/tetrahedron intersection).
psi_add_gl_executable(TestPsiDegenerateProjections)
psi_add_render_test(DegenerateProjections TestPsiDegenerateProjections FAN TIMEOUT 120)

# A mesh whose visibility order has cycles (a twisted Delaunay mesh): MPVONC's cycle breaks
# counted, the image against the exact reference, which needs no order.
psi_add_gl_executable(TestPsiCyclicOrder VTK::FiltersCore)
psi_add_render_test(CyclicOrder TestPsiCyclicOrder)

# Several volumes in one renderer drawn intermixed: disjoint volumes equal their union drawn as
# one, in either order and from three views; their own transfer functions; one hidden.
psi_add_gl_executable(TestPsiIntermixedVolumes VTK::FiltersCore VTK::FiltersExtraction)
psi_add_render_test(IntermixedVolumes TestPsiIntermixedVolumes)

psi_add_gl_executable(TestPsiVisibilityOrder)
add_test(NAME PsiRendering.VisibilityOrder COMMAND TestPsiVisibilityOrder)
set_tests_properties(PsiRendering.VisibilityOrder PROPERTIES TIMEOUT 120)

# Translucent geometry intermixed with the volume through VTK's dual depth peeling, against the
# reference ray caster compositing the surfaces' layers.
psi_add_gl_executable(TestPsiTranslucentGeometry)
psi_add_render_test(TranslucentGeometry TestPsiTranslucentGeometry TIMEOUT 300)

# Meshes past the driver's buffer limits (lowered for the test): the compute projector in many
# passes with the same image, and one clear error where a mesh cannot be drawn.
psi_add_gl_executable(TestPsiDriverLimits)
add_test(NAME PsiRendering.DriverLimits COMMAND TestPsiDriverLimits)

# The ways 'Auto' times on the first frames: each the fixed way's image within 1/255, a choice
# the read-outs name, explicit settings honoured, and what decides measuring again.
psi_add_gl_executable(TestPsiMeasuredChoice)
add_test(NAME PsiRendering.MeasuredChoice COMMAND TestPsiMeasuredChoice)

# The shipped GLSL of each method on the GPU against its C++ version.
find_package(OpenGL REQUIRED)
psi_add_gl_executable(TestIntegrationGLSL OpenGL::GL)
add_test(NAME PsiRendering.IntegrationGLSL COMMAND TestIntegrationGLSL)

# Full pre-integration on a mesh whose cell sizes span three decades: the table's logarithmic
# length axis, its lookups against the exact integral, and a render against the CPU ray caster.
psi_add_gl_executable(TestPreIntegrationGraded)
add_test(NAME PsiRendering.PreIntegrationGraded COMMAND TestPreIntegrationGraded
  "${CMAKE_BINARY_DIR}/Testing/Images")
set_tests_properties(PsiRendering.PreIntegrationGraded PROPERTIES TIMEOUT 90)

# The composed shader programs (PsiShaderComposer): every feature's code exactly when it is on,
# the geometry-shader budget, and a representative subset compiled by the driver without a word
# from the compiler. Mesa's on-disk shader cache is off for it: a cached program is not compiled
# again, and its warnings are not said again.
psi_add_gl_executable(TestShaderComposition)
add_test(NAME PsiRendering.ShaderComposition COMMAND TestShaderComposition)
set_tests_properties(PsiRendering.ShaderComposition PROPERTIES
  ENVIRONMENT "MESA_SHADER_CACHE_DISABLE=true"
  TIMEOUT 600)

# The mapper holds the one settings type: the integration method clamped to the method table
# (through psi::SetClamped), named from it, its default the settings' (GL-free).
add_executable(TestMapperSettings Cxx/TestMapperSettings.cxx)
target_link_libraries(TestMapperSettings PRIVATE PsiVolume::Rendering)
add_test(NAME PsiRendering.MapperSettings COMMAND TestMapperSettings)

# The mapper from plain VTK Python (the interpreter VTK was built for, not pvpython): the wrapped
# Rendering module (cmake/PsiVolumeWrapPython.cmake) renders a tetrahedral mesh with VTK's
# vtkmodules alone, like VTK's own projected tetrahedra, and no ParaView module or library is
# loaded into the process.
if (TARGET PsiVolumeVTKPython)
  find_package(Python3 ${Python3_VERSION} EXACT COMPONENTS Interpreter)
endif ()
if (TARGET PsiVolumeVTKPython AND Python3_Interpreter_FOUND)
  add_test(NAME PsiRendering.PlainVTKPython
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_plain_vtk.py"
      "${CMAKE_BINARY_DIR}/${PSI_PYTHON_DESTINATION}")
  set_tests_properties(PsiRendering.PlainVTKPython PROPERTIES TIMEOUT 120)
endif ()

# Two volumes sharing space, intermixed, against the exact reference of two media: within the
# documented bound, and closer as the cells get smaller.
psi_add_gl_executable(TestPsiInterpenetratingVolumes)
add_test(NAME PsiRendering.InterpenetratingVolumes COMMAND TestPsiInterpenetratingVolumes
  "${CMAKE_BINARY_DIR}/Testing/Images" --projector geometry)
