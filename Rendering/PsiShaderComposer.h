// PsiShaderComposer: composes the Psi Volume shader program for one feature set, the way VTK's
// vtkVolumeShaderComposer.h composes vtkOpenGLGPUVolumeRayCastMapper's: one replacement per
// concern. GL-free (plain strings), so it is testable without a context.
//
// The templates Shaders/PsiVolumeVS.glsl, PsiVolumeGS.glsl and PsiVolumeFS.glsl hold tags
// `//PSI::<Feature>::<Site>` on lines of their own. Each feature lives in its own file,
// Shaders/Psi<Feature><Stage>.glsl, made of sections: a line `//PSI::<Feature>::<Site>` starts
// the section that replaces that tag. A section may hold tags of other features (e.g. the early
// discard of a marching-tetrahedra piece inside PsiIsoTrianglesGS.glsl), which are replaced
// after it. A feature that is off is not substituted: its tags are replaced by nothing, so the
// composed program contains only what the feature set calls for. #defines remain only for counts
// (PSI_GS_MAX_VERTICES, PSI_ISO_COUNT, PSI_MAX_LIGHTS, PSI_TF_NODES_MAX, PSI_MAX_SPLITS).
#ifndef PsiShaderComposer_h
#define PsiShaderComposer_h

#include "PsiShaderFeatures.h"
#include "PsiStageInterface.h"
#include "PsiVolumeRenderingModule.h"

#include <string>
#include <vector>

namespace psi
{

/// Output components per geometry-shader vertex: gl_Position plus psi::GeometryOutputs(f).
PSIVOLUMERENDERING_EXPORT int GeometryOutputComponentsPerVertex(const ShaderFeatures& f);
/// Whether the composed geometry shader fits GL_MAX_GEOMETRY_OUTPUT_VERTICES and
/// GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS.
PSIVOLUMERENDERING_EXPORT bool FitsGeometryOutputLimits(
  const ShaderFeatures& f, int maxVertices, int maxTotalComponents);

/// The GLSL of integration method `method` (Shaders/PsiIntegrate*.glsl), which defines
/// vec4 integrateSegment(float sf, float sb, float D); methods out of range give partial
/// pre-integration, the mapper's default.
PSIVOLUMERENDERING_EXPORT const char* IntegratorSource(int method);

struct ShaderSources
{
  std::string Vertex, Geometry, Fragment;
};

/// Composes the program for `f`. `integratorSource` is substituted at //PSI::Integrator::Impl;
/// nullptr means IntegratorSource(f.Method). The integrator's inputs (Psi table, unit distance,
/// pre-integrated table: PsiIntegratorInputsFS.glsl) are declared when its source uses them.
/// `form` (PsiStageInterface.h): Vertex and Geometry as shaders, or as the functions
/// psiVertexMain and psiGeometryMain of the compute-shader projector; Fragment is the same.
/// Throws std::logic_error when a section finds no tag to replace (a template error).
PSIVOLUMERENDERING_EXPORT ShaderSources ComposeShaders(const ShaderFeatures& f,
  const char* integratorSource = nullptr, StageForm form = StageForm::Stages);

} // namespace psi

#endif
