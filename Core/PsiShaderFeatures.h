// PsiShaderFeatures: the features one 'Psi Volume' shader program is composed from, as the frame
// plan decides them (PsiFramePlan.h) and both composers read them (PsiShaderComposer.h, the
// stages' interface in PsiStageInterface.h). GL-free.
#ifndef PsiShaderFeatures_h
#define PsiShaderFeatures_h

#include "PsiIntegrationMethods.h"
#include "PsiSettings.h" // the defaults
#include "PsiVolumeCoreModule.h"

#include <string>

// Plain C++ for the planner, the composers and the tests; VTK's wrappers need none of it.
#ifndef __VTK_WRAP__
namespace psi
{

/// The features one shader program is composed from.
struct PSIVOLUMECORE_EXPORT ShaderFeatures
{
  /// Integration method, 0..6 (the numbers of psi::Method, Core/PsiIntegrationMethods.h); the
  /// settings' default.
  int Method = static_cast<int>(Settings().IntegrationMethod);
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
  int MaxAdaptiveNodes = psi::MaxAdaptiveNodes;
  int MaxLights = 8;
  /// Benchmarks only: every fragment writes one constant color, and the compiler drops the ray
  /// and its integration: what the same triangles cost without shading (the raster floor).
  bool RasterFloor = false;

  bool operator==(const ShaderFeatures& o) const;
  bool operator!=(const ShaderFeatures& o) const { return !(*this == o); }

  /// The feature set as one "#define"-style line per feature in effect (PSI_OPAQUE_CLIP,
  /// PSI_SILHOUETTE, PSI_EXACT_SEGMENTS, PSI_NEAR_CLIP, PSI_ISO_COUNT n, PSI_MAX_LIGHTS n,
  /// PSI_ISO_SMOOTH, PSI_ISO_TRIANGLES, PSI_GS_MAX_VERTICES n, PSI_ISO_PER_FRAGMENT,
  /// PSI_EARLY_DISCARD, PSI_SEPARATE_OPACITY, PSI_DEPTH_PEEL, PSI_ADAPTIVE, PSI_TF_NODES_MAX n):
  /// the program cache's key (Key) and the mapper's read-out of the last frame's features. The
  /// composed program itself does not use these lines: its features are substituted sections.
  std::string Defines() const;
  /// Identifies the composed program: Defines() plus the method. Two feature sets with the same
  /// key compose the same sources.
  std::string Key() const;
};

/// Whether `f` draws a separate opacity array: with silhouettes and without adaptive sampling (the
/// mapper chooses so); another feature set ignores it.
PSIVOLUMECORE_EXPORT bool SeparateOpacityDrawn(const ShaderFeatures& f);

/// Whether `f` draws within depth peeling: only with silhouettes (the frame plan chooses so).
PSIVOLUMECORE_EXPORT bool DepthPeelDrawn(const ShaderFeatures& f);

/// Geometry-shader output vertices: the largest projected decomposition (the fan's 8 vertices:
/// class 2, a strip of 5 and one of 3; the silhouette and the near-plane screen box have 4), and
/// with marching tetrahedra that once per volume piece (IsoCount + 1) plus a 4-vertex strip per
/// surface.
PSIVOLUMECORE_EXPORT int GeometryOutputVertices(const ShaderFeatures& f);
/// Triangles one tetrahedron emits at most: 4 for its fan (class 2; 2 for its silhouette or the
/// near-plane screen box), and with marching
/// tetrahedra 4 per volume piece plus 2 per surface. The compute-shader projector sizes its
/// slots with it.
PSIVOLUMECORE_EXPORT int ProjectedTrianglesMax(const ShaderFeatures& f);

} // namespace psi

#endif // __VTK_WRAP__

#endif
