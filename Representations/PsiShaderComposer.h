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

#include "PsiStageInterface.h"
#include "PsiVolumeRepresentationsModule.h"

#include <string>
#include <vector>

namespace psi
{

/// The features one shader program is composed from.
struct PSIVOLUMEREPRESENTATIONS_EXPORT ShaderFeatures
{
  /// Integration method, 0..6 (psi::Method, Core/PsiIntegrationMethods.h; the same numbering as
  /// vtkPsiVolumeMapper's IntegrationMethod).
  int Method = 1;
  /// Perspective: exact segments from the front point and the back plane (PsiExactSegments*.glsl)
  /// instead of the screen-linear (s_f, s_b, l) triple (PsiHAPTSegments*.glsl).
  bool ExactSegments = false;
  /// Each projection drawn as its silhouette (1-2 triangles) whose fragments intersect their ray
  /// with the face planes (PsiRaySegments*.glsl), exact in both projections, instead of the 1-4
  /// triangles of the fan (ExactSegments or the screen-linear triple).
  bool Silhouette = false;
  /// The near plane cuts the mesh: cut cells are intersected per fragment (PsiNearClip*.glsl).
  bool NearClip = false;
  /// Opaque geometry inside the volume: cut cells are integrated up to it (PsiOpaqueClipFS.glsl).
  bool OpaqueClip = false;
  /// Cells (or, with IsoTriangles, pieces) meeting only zero opacity emit nothing
  /// (PsiEarlyDiscardGS.glsl).
  bool EarlyDiscard = false;
  /// Number of isovalues; 0: no isosurfaces.
  int IsoCount = 0;
  /// Isosurface normals from smoothed point gradients (else the cell's gradient).
  bool IsoSmooth = false;
  /// With IsoCount > 0: marching tetrahedra in the geometry shader (PsiIsoTriangles*.glsl), else
  /// per-fragment isosurfaces (PsiIsoPerFragment*.glsl).
  bool IsoTriangles = false;
  /// Segments split at transfer-function nodes (PsiAdaptiveFS.glsl).
  bool Adaptive = false;
  /// Opacity from a second scalar per point (ParaView's separate opacity array,
  /// PsiSeparateOpacity*.glsl); needs Silhouette, and not Adaptive.
  bool SeparateOpacity = false;
  /// Drawn within VTK's dual depth peeling: each draw integrates the segments' parts inside a
  /// depth interval the pass gives per pixel (PsiDepthPeelFS.glsl); needs Silhouette.
  bool DepthPeel = false;
  int MaxAdaptiveNodes = 64;
  int MaxLights = 8;

  bool operator==(const ShaderFeatures& o) const;
  bool operator!=(const ShaderFeatures& o) const { return !(*this == o); }

  /// The feature set as one "#define" line per feature, in the mapper's historical form
  /// (PSI_OPAQUE_CLIP, PSI_EXACT_SEGMENTS, PSI_NEAR_CLIP, PSI_ISO_COUNT n, PSI_MAX_LIGHTS n,
  /// PSI_ISO_SMOOTH, PSI_ISO_TRIANGLES, PSI_GS_MAX_VERTICES n, PSI_ISO_PER_FRAGMENT,
  /// PSI_EARLY_DISCARD, PSI_ADAPTIVE, PSI_TF_NODES_MAX n); only what is in effect is listed.
  /// A description: the composed program does not use these defines.
  std::string Defines() const;
  /// Identifies the composed program: Defines() plus the method. Two feature sets with the same
  /// key compose the same sources.
  std::string Key() const;
};

/// Whether a mapper's Decomposition setting (0 silhouette, 1 fan, 2 auto) draws silhouettes:
/// auto follows the environment's PSI_DECOMPOSITION ("fan" or "silhouette", a site's choice),
/// else the silhouette.
PSIVOLUMEREPRESENTATIONS_EXPORT bool SilhouetteChosen(int decomposition);

/// Whether `f` draws a separate opacity array: with silhouettes and without adaptive sampling (the
/// mapper chooses so); another feature set ignores it.
PSIVOLUMEREPRESENTATIONS_EXPORT bool SeparateOpacityDrawn(const ShaderFeatures& f);

/// Geometry-shader output vertices: the largest projected decomposition (the fan's 8 vertices:
/// class 2, a strip of 5 and one of 3; the silhouette and the near-plane screen box have 4), and
/// with marching tetrahedra that once per volume piece (IsoCount + 1) plus a 4-vertex strip per
/// surface.
PSIVOLUMEREPRESENTATIONS_EXPORT int GeometryOutputVertices(const ShaderFeatures& f);
/// Triangles one tetrahedron emits at most: 4 for its fan (class 2; 2 for its silhouette or the
/// near-plane screen box), and with marching
/// tetrahedra 4 per volume piece plus 2 per surface. The compute-shader projector sizes its
/// slots with it.
PSIVOLUMEREPRESENTATIONS_EXPORT int ProjectedTrianglesMax(const ShaderFeatures& f);
/// Output components per geometry-shader vertex: gl_Position plus psi::GeometryOutputs(f).
PSIVOLUMEREPRESENTATIONS_EXPORT int GeometryOutputComponentsPerVertex(const ShaderFeatures& f);
/// Whether the composed geometry shader fits GL_MAX_GEOMETRY_OUTPUT_VERTICES and
/// GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS.
PSIVOLUMEREPRESENTATIONS_EXPORT bool FitsGeometryOutputLimits(
  const ShaderFeatures& f, int maxVertices, int maxTotalComponents);

/// The GLSL of integration method `method` (Shaders/PsiIntegrate*.glsl), which defines
/// vec4 integrateSegment(float sf, float sb, float D); methods out of range give partial
/// pre-integration, the mapper's default.
PSIVOLUMEREPRESENTATIONS_EXPORT const char* IntegratorSource(int method);

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
PSIVOLUMEREPRESENTATIONS_EXPORT ShaderSources ComposeShaders(const ShaderFeatures& f,
  const char* integratorSource = nullptr, StageForm form = StageForm::Stages);

} // namespace psi

#endif
