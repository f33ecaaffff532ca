// PsiFramePlan: what one frame simulates, decided in one place from the user's settings
// (psi::Settings, Core/PsiSettings.h, which resolves each 'Auto') and the
// facts of the scene, with no GL call and no table in sight: "simulate only the effects a scene
// calls for". The mapper gathers the facts (camera, other props, depth peeling, the sampled
// transfer function's zero regions and its adaptive nodes, the driver's geometry-shader limits),
// asks psi::PlanFrame, then updates and binds only the tables the plan names, and composes the
// program for the plan's features. GL-free, tested without a context (TestFramePlan).
#ifndef PsiFramePlan_h
#define PsiFramePlan_h

#include "PsiMeasuredChoice.h"
#include "PsiSettings.h"
#include "PsiShaderFeatures.h"
#include "PsiVolumeCoreModule.h"

#include <functional>

/// What the frame finds in the scene and in its data.
struct PsiSceneFacts
{
  bool Parallel = false;      ///< parallel projection
  bool NearPlaneCuts = false; ///< the near plane cuts the mesh's bounds
  bool OpaqueOverlaps =
    false;                  ///< opaque geometry overlaps the volume (psi::OpaqueGeometryOverlaps)
  bool SceneOpaque = false; ///< the scene has opaque geometry anywhere
  bool DepthPeeled = false; ///< drawn within a depth-peeling stage (not Plain)
  bool SeparateOpacity = false; ///< the mesh carries a separate opacity array
  bool ZeroOpacity = false;     ///< the opacity function has zero regions over the range
  bool NodesFaithful = true;    ///< the adaptive nodes follow the function (PsiAdaptiveNodes)
  double TableDeviation = 0;    ///< how far the sampled table misses the nodes
  /// The largest opacity a ray through the mesh's bounds can reach (psi::MaxRayOpacity over the
  /// bounds' diagonal): 1 when unknown.
  double MaxRayOpacity = 1;
  /// The driver can mask the opaque pixels between draws (PsiOpacityMasks::IsSupported).
  bool MasksOpaquePixels = true;
  /// The driver runs the compute projector (OpenGL 4.3, PsiComputeProjector::Chosen).
  bool ComputeAvailable = false;
  /// Whether the geometry shader composed for these features fits the driver's output limits
  /// (the mapper asks psi::FitsGeometryOutputLimits with GL_MAX_GEOMETRY_OUTPUT_VERTICES and
  /// GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS); empty: not asked, it fits.
  std::function<bool(const psi::ShaderFeatures&)> GeometryOutputFits;
};

namespace psi
{
/// Front-to-back compositing stops shading a pixel once its opacity reaches this: what lies
/// behind can still add at most 1 - 0.999 of full intensity to any channel, a quarter of one
/// 8-bit step (1/255).
constexpr double SaturatedOpacity = 0.999;
} // namespace psi

struct PsiFramePlan
{
  psi::ShaderFeatures Features;
  /// The tables the features read besides the transfer function (always read).
  struct
  {
    bool OpacityPrefix = false;              ///< early discard's prefix counts
    bool PartialPreIntegrationTable = false; ///< partial pre-integration's Psi table
    bool PreIntegration = false;             ///< Röttger's 3D table
    bool AdaptiveNodes = false;              ///< the nodes as uniforms
    bool Gradients = false;                  ///< smoothed point gradients (smooth isosurfaces)
  } Tables;
  /// Copy the scene's depth for the depth test (opaque geometry, or the shaders sample it).
  bool SceneDepth = false;
  /// How the frame is drawn: front to back ("under", the nearest tetrahedra first, shading
  /// stopped where a pixel's opacity has reached psi::SaturatedOpacity: early ray termination)
  /// or back to front ("over"), with how many masks; the projector. Each 'Auto' resolved to its
  /// default; psi::MeasuredChoice may put another of the Open ways, which draw the same image,
  /// in its place (the mapper's ChooseWay). The decomposition is Features.Silhouette.
  psi::DrawWay Way;
  psi::DrawWayOptions Open;
  /// The way is an alternative to the plan's own being timed (psi::MeasuredChoice): a draw
  /// error of its own is not the user's (the way just loses).
  bool Trial = false;
  /// Full pre-integration asked for with a separate opacity array draws as partial
  /// pre-integration: Röttger's table tabulates one scalar for color and opacity.
  bool MethodReplaced = false;
};

/// The frame's plan (the rules are commented where they are applied, PsiFramePlan.cxx).
PSIVOLUMECORE_EXPORT PsiFramePlan PlanFrame(
  const psi::Settings& settings, const PsiSceneFacts& facts);
/// Whether the scene calls for the adaptive nodes to be computed before the plan: adaptive
/// sampling is on or 'Auto' (the nodes' deviation decides 'Auto').
PSIVOLUMECORE_EXPORT bool NeedsAdaptiveNodes(const psi::Settings& settings);
/// Whether isosurfaces may be drawn by marching tetrahedra (then the facts need the driver's
/// geometry-shader limits).
PSIVOLUMECORE_EXPORT bool MayUseIsoTriangles(
  const psi::Settings& settings, const PsiSceneFacts& facts);

#endif
