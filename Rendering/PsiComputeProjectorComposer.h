// PsiComputeProjectorComposer: the programs of the compute-shader projector, composed by
// psi::ComposeShaders from the same templates as the geometry-shader projector's, so that both
// projectors run the same classification and emission code for every feature set. GL-free (plain
// strings).
//
// The compute shader (Shaders/PsiProjectCS.glsl) holds the vertex and geometry code in their
// function form (psi::StageForm::Functions); the draw program is a pass-through vertex shader
// (Shaders/PsiProjectedVS.glsl) that fetches each projected vertex and hands the geometry code's
// outputs (psi::GeometryOutputs), under the same names and qualifiers, to the unchanged fragment
// shader.
#ifndef PsiComputeProjectorComposer_h
#define PsiComputeProjectorComposer_h

#include "PsiShaderComposer.h"

#include <string>

namespace psi
{

struct ComputeProjectorSources
{
  std::string Compute;    ///< complete, with its #version line (compiled by the mapper)
  std::string Vertex;     ///< pass-through, //VTK::System::Dec left for VTK's shader cache
  std::string Fragment;   ///< psi::ComposeShaders(f).Fragment
  int SlotVertices = 0;   ///< vertices one tetrahedron may write (GeometryOutputVertices)
  int SlotTriangles = 0;  ///< triangles one tetrahedron may write (ProjectedTrianglesMax)
  int Vec4sPerVertex = 0; ///< clip position plus one vec4 per output vec4 (matrix column)
};

/// Composes the compute projector for `f`. `integratorSource` as for psi::ComposeShaders.
/// Throws std::logic_error when a stage output has a type it cannot pass on.
PSIVOLUMERENDERING_EXPORT ComputeProjectorSources ComposeComputeProjector(
  const ShaderFeatures& f, const char* integratorSource = nullptr);

} // namespace psi

#endif
