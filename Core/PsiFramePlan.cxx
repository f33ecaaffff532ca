#include "PsiFramePlan.h"

#include "PsiIntegrationMethods.h"

#include <algorithm>
#include <vector>

namespace
{
// Röttger's table tabulates one scalar for color and opacity: with a separate opacity array full
// pre-integration draws as partial pre-integration (the tables and the program both follow).
psi::Method DrawnMethod(const psi::Settings& s, const PsiSceneFacts& facts)
{
  return facts.SeparateOpacity &&
      psi::GetIntegrationMethodInfo(s.IntegrationMethod).NeedsPreIntegrationTable
    ? psi::Method::PartialPreIntegration
    : s.IntegrationMethod;
}

// Marching tetrahedra as psi::UsesMarchingTetrahedra resolves it, and only when the composed
// geometry shader fits the driver's output limits; else per fragment.
bool IsoTriangles(const psi::Settings& s, const PsiSceneFacts& facts, psi::ShaderFeatures f)
{
  if (!MayUseIsoTriangles(s, facts))
  {
    return false;
  }
  f.IsoTriangles = true;
  return !facts.GeometryOutputFits || facts.GeometryOutputFits(f);
}

// Whether front to back with early ray termination can draw the frame: the driver can mask
// opaque pixels, and not within depth peeling, whose passes composite the volume with the
// translucent geometry between the peels back to front.
bool FrontToBackPossible(const PsiSceneFacts& facts, const psi::ShaderFeatures& f)
{
  return facts.MasksOpaquePixels && !f.DepthPeel;
}

// Whether a pixel can turn opaque: the volume's opacity can reach psi::SaturatedOpacity along a
// ray through the bounds, or an isosurface may hide what is behind it. Where none can, front to
// back has nothing to stop and its masks only cost.
bool CanSaturate(const psi::Settings& s, const PsiSceneFacts& facts)
{
  const std::vector<float> isoOpacities = s.Isosurfaces().Opacities;
  return facts.MaxRayOpacity >= psi::SaturatedOpacity ||
    std::any_of(isoOpacities.begin(), isoOpacities.end(), [](float a) { return a > 0; });
}

// The plan's way with each 'Auto' at its default, and the alternatives that draw the same
// image, open to measurement where the setting is 'Auto' (psi::MeasuredChoice). Front to back
// when 'On' (with the default masks), or under 'Auto' where a pixel can turn opaque, with back
// to front and fewer masks timed against it.
// The compute projector where the driver runs it. Not the fan: it is not the silhouettes' image
// at isolated pixels (8/255 at one pixel of TestPsiMeasuredChoice's view, 38/255 at one of
// TestPsiVolumeRender's, where the silhouettes are within 1.5/255 of the exact image), and was
// the slower on every benchmark scene. Within depth peeling (one call per peeling stage)
// nothing is measured.
void PlanWay(PsiFramePlan& plan, const psi::Settings& s, const PsiSceneFacts& facts)
{
  const psi::ShaderFeatures& f = plan.Features;
  using ERT = psi::EarlyRayTerminations;
  const bool possible = FrontToBackPossible(facts, f);
  const bool autoFront = s.EarlyRayTermination == ERT::Auto && possible && CanSaturate(s, facts);
  plan.Way.FrontToBack = (s.EarlyRayTermination == ERT::On && possible) || autoFront;
  plan.Way.ComputeProjector = psi::UsesComputeProjector(s);
  plan.Open.Direction = autoFront;
  plan.Open.MasksPerFrame = autoFront;
  plan.Open.Projector = s.Projector == psi::Projectors::Auto && facts.ComputeAvailable;
  if (facts.DepthPeeled)
  {
    plan.Open = psi::DrawWayOptions();
  }
}
} // namespace

bool NeedsAdaptiveNodes(const psi::Settings& s)
{
  return s.AdaptiveSampling != psi::AdaptiveModes::Off;
}

bool MayUseIsoTriangles(const psi::Settings& s, const PsiSceneFacts& facts)
{
  return s.Isosurfaces().Count() > 0 && psi::UsesMarchingTetrahedra(s, facts.ZeroOpacity);
}

PsiFramePlan PlanFrame(const psi::Settings& s, const PsiSceneFacts& facts)
{
  PsiFramePlan plan;
  psi::ShaderFeatures& f = plan.Features;
  const psi::Method drawn = DrawnMethod(s, facts);
  f.Method = static_cast<int>(drawn);
  plan.MethodReplaced = drawn != s.IntegrationMethod;
  f.ExactSegments = !facts.Parallel && s.ExactPerspectiveSegments;
  // within depth peeling, the silhouettes' exact segments are clipped to the pass's intervals
  f.DepthPeel = facts.DepthPeeled;
  f.Silhouette = psi::UsesSilhouettes(s) || f.DepthPeel;
  f.NearClip = facts.NearPlaneCuts;
  f.OpaqueClip = facts.OpaqueOverlaps;
  f.IsoCount = s.Isosurfaces().Count();
  // unlit isosurfaces need no normals; flat ones take each cell's gradient
  f.IsoSmooth = f.IsoCount > 0 && s.IsosurfaceShading == psi::IsosurfaceShadings::Smooth;
  f.IsoTriangles = IsoTriangles(s, facts, f);
  // Early discard (Maximo et al. 2010 §3.5) only when the opacity function has zero regions,
  // and not with per-fragment isosurfaces (visible where the volume is transparent; marching
  // tetrahedra still emit the surfaces of a cell whose volume pieces are dropped).
  f.EarlyDiscard = s.EarlyDiscard && facts.ZeroOpacity && (f.IsoCount == 0 || f.IsoTriangles);
  // Adaptive sampling (Moreland's dissertation §4.3) when on, or under 'Auto' when the sampled
  // table misses the function's nodes; never when the nodes cannot follow the function.
  f.Adaptive = facts.NodesFaithful && psi::UsesAdaptiveSampling(s, facts.TableDeviation);
  f.MaxAdaptiveNodes = psi::MaxAdaptiveNodes;
  f.RasterFloor = s.RasterFloor;
  // A separate opacity array: drawn with silhouettes, whose fragments carry both scalars; not
  // with adaptive sampling (nodes of one scalar); early discard judged on the opacity scalar,
  // per cell, so not per marching-tetrahedra piece.
  f.SeparateOpacity = facts.SeparateOpacity;
  if (f.SeparateOpacity)
  {
    f.Silhouette = true;
    f.Adaptive = false;
    f.EarlyDiscard = f.EarlyDiscard && !f.IsoTriangles;
  }
  plan.Tables.OpacityPrefix = f.EarlyDiscard;
  const psi::IntegrationMethodInfo& method = psi::GetIntegrationMethodInfo(drawn);
  plan.Tables.PartialPreIntegrationTable = method.NeedsPsiTable;
  plan.Tables.PreIntegration = method.NeedsPreIntegrationTable;
  plan.Tables.AdaptiveNodes = f.Adaptive;
  plan.Tables.Gradients = f.IsoSmooth;
  plan.SceneDepth = facts.SceneOpaque || f.NearClip || f.OpaqueClip;
  PlanWay(plan, s, facts);
  return plan;
}
