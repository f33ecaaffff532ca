// The frame plan (Core/PsiFramePlan.h), without a GL context: each effect is planned
// exactly when the scene calls for it, and each table exactly when a planned feature reads it.
// The rules: the integration method and its tables; early discard only with zero opacity and not
// with per-fragment isosurfaces; marching tetrahedra when asked for or under 'Auto' with early
// discard, and only within the driver's geometry-shader limits; adaptive sampling on, off and
// 'Auto' against the table's deviation, never with unfaithful nodes; a separate opacity array
// (silhouettes, no adaptive sampling, full pre-integration drawn as partial, no early discard
// with marching tetrahedra); depth peeling
// (silhouettes); the scene depth copied only when something tests or samples it; front to back
// with early ray termination only when a pixel can turn opaque, the driver can mask it, and not
// within depth peeling.
#include "PsiFramePlan.h"
#include "PsiIntegrationMethods.h"
#include "PsiSettings.h"
#include "PsiTestCheck.h"
#include "PsiTransferFunctionAnalysis.h"
#include "PsiTransferFunctionTable.h"

#include <cmath>
#include <cstdlib>

namespace
{
// A scene with nothing special: no isosurfaces, an opacity without zero regions.
psi::Settings Settings()
{
  psi::Settings s;
  s.Decomposition = psi::Decompositions::Silhouette;
  return s;
}

// A driver whose geometry-shader output limits the composed program fits, or not (the mapper
// asks psi::FitsGeometryOutputLimits, tested by TestShaderComposition); the plan asks only
// for marching tetrahedra.
PsiSceneFacts Facts(bool geometryOutputFits = true)
{
  PsiSceneFacts f;
  f.GeometryOutputFits = [geometryOutputFits](const psi::ShaderFeatures& features)
  {
    PSI_CHECK(features.IsoTriangles, "the output limits asked for marching tetrahedra only");
    return geometryOutputFits;
  };
  return f;
}

void TestMethodTables()
{
  for (int m = 0; m < psi::NumberOfIntegrationMethods(); ++m)
  {
    psi::Settings s = Settings();
    s.IntegrationMethod = psi::Method(m);
    const PsiFramePlan plan = PlanFrame(s, Facts());
    const psi::IntegrationMethodInfo& info = psi::GetIntegrationMethodInfo(psi::Method(m));
    PSI_CHECK(plan.Features.Method == m, "method %d drawn as %d", m, plan.Features.Method);
    PSI_CHECK(
      plan.Tables.PartialPreIntegrationTable == info.NeedsPsiTable, "method %d: Psi table", m);
    PSI_CHECK(
      plan.Tables.PreIntegration == info.NeedsPreIntegrationTable, "method %d: 3D table", m);
    PSI_CHECK(!plan.Tables.OpacityPrefix && !plan.Tables.AdaptiveNodes && !plan.Tables.Gradients,
      "method %d: a table no feature reads", m);
    PSI_CHECK(!plan.MethodReplaced && !plan.SceneDepth, "method %d: plain scene", m);
  }
}

void TestEarlyDiscard()
{
  psi::Settings s = Settings();
  PsiSceneFacts facts = Facts();
  PSI_CHECK(!PlanFrame(s, facts).Features.EarlyDiscard, "early discard without zero opacity");
  facts.ZeroOpacity = true;
  PsiFramePlan plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Features.EarlyDiscard && plan.Tables.OpacityPrefix, "zero opacity: discard");
  s.EarlyDiscard = false;
  PSI_CHECK(!PlanFrame(s, facts).Tables.OpacityPrefix, "early discard switched off");
  s.EarlyDiscard = true;
  s.IsosurfaceValues = { 0.2, 0.6 };
  s.IsosurfaceMethod = psi::IsosurfaceMethods::PerFragment;
  plan = PlanFrame(s, facts);
  PSI_CHECK(!plan.Features.EarlyDiscard && !plan.Features.IsoTriangles,
    "per-fragment isosurfaces are seen where the volume is transparent: no discard");
}

void TestIsosurfaces()
{
  psi::Settings s = Settings();
  PsiSceneFacts facts = Facts();
  s.IsosurfaceValues = { 0.2, 0.4, 0.6 };
  PSI_CHECK(!PlanFrame(s, facts).Features.IsoTriangles, "'Auto' without zero opacity");
  facts.ZeroOpacity = true;
  PsiFramePlan plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Features.IsoTriangles && plan.Features.EarlyDiscard, "'Auto' with zero opacity");
  PSI_CHECK(plan.Tables.Gradients && plan.Features.IsoSmooth, "smooth shading reads gradients");
  s.IsosurfaceShading = psi::IsosurfaceShadings::Flat;
  PSI_CHECK(!PlanFrame(s, facts).Tables.Gradients, "flat shading needs no gradients");
  s.IsosurfaceShading = psi::IsosurfaceShadings::Unlit;
  PSI_CHECK(!PlanFrame(s, facts).Tables.Gradients && PlanFrame(s, facts).Features.IsoCount == 3,
    "unlit isosurfaces need no gradients");
  s.IsosurfaceShading = psi::IsosurfaceShadings::Flat;
  facts.GeometryOutputFits = Facts(false).GeometryOutputFits; // a driver whose budget they exceed
  PSI_CHECK(MayUseIsoTriangles(s, facts) && !PlanFrame(s, facts).Features.IsoTriangles,
    "marching tetrahedra beyond the geometry-shader limits");
  facts = Facts();
  s.IsosurfaceMethod = psi::IsosurfaceMethods::MarchingTetrahedra;
  PSI_CHECK(PlanFrame(s, facts).Features.IsoTriangles, "marching tetrahedra asked for");
  s.IsosurfaceValues.clear();
  PSI_CHECK(!MayUseIsoTriangles(s, facts), "no isovalues: no limits to ask the driver");
  s.IsosurfaceValues = { std::nan(""), std::nan("") };
  PSI_CHECK(!MayUseIsoTriangles(s, facts) && PlanFrame(s, facts).Features.IsoCount == 0 &&
      !PlanFrame(s, facts).Features.IsoTriangles,
    "only non-finite isovalues: no isosurfaces");
}

void TestAdaptive()
{
  psi::Settings s = Settings();
  PsiSceneFacts facts = Facts();
  facts.TableDeviation = 0.5 * psi::AdaptiveAutoDeviation;
  PSI_CHECK(!PlanFrame(s, facts).Features.Adaptive, "'Auto' where the table follows the nodes");
  facts.TableDeviation = 2 * psi::AdaptiveAutoDeviation;
  PsiFramePlan plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Features.Adaptive && plan.Tables.AdaptiveNodes, "'Auto' where the table misses");
  facts.NodesFaithful = false;
  PSI_CHECK(!PlanFrame(s, facts).Features.Adaptive, "nodes that cannot follow the function");
  facts = Facts();
  s.AdaptiveSampling = psi::AdaptiveModes::On;
  PSI_CHECK(PlanFrame(s, facts).Features.Adaptive, "on");
  s.AdaptiveSampling = psi::AdaptiveModes::Off;
  facts.TableDeviation = 1;
  PSI_CHECK(!PlanFrame(s, facts).Features.Adaptive && !NeedsAdaptiveNodes(s), "off");
}

void TestSeparateOpacityAndPeeling()
{
  psi::Settings s = Settings();
  s.Decomposition = psi::Decompositions::Fan;
  s.AdaptiveSampling = psi::AdaptiveModes::On;
  s.IntegrationMethod = psi::Method::FullPreIntegration;
  PsiSceneFacts facts = Facts();
  PsiFramePlan plan = PlanFrame(s, facts);
  PSI_CHECK(!plan.Features.Silhouette && plan.Features.Adaptive && plan.Tables.PreIntegration,
    "fan, adaptive, full pre-integration");
  facts.SeparateOpacity = true;
  plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Features.Silhouette && !plan.Features.Adaptive && !plan.Tables.AdaptiveNodes,
    "a separate opacity array: silhouettes, no nodes");
  PSI_CHECK(plan.MethodReplaced && !plan.Tables.PreIntegration &&
      plan.Tables.PartialPreIntegrationTable &&
      plan.Features.Method == static_cast<int>(psi::Method::PartialPreIntegration),
    "full pre-integration with a separate opacity array draws as partial");
  // With isosurfaces and zero opacity, 'Auto' draws marching tetrahedra; early discard would
  // test their volume pieces on the colored scalar, so none with a separate opacity array.
  s = Settings();
  s.IsosurfaceValues = { 0.2, 0.6 };
  facts.ZeroOpacity = true;
  plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Features.IsoTriangles && !plan.Features.EarlyDiscard && !plan.Tables.OpacityPrefix,
    "separate opacity, zero opacity, 'Auto' isosurfaces: marching tetrahedra, no early discard");
  facts = Facts();
  facts.DepthPeeled = true;
  plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Features.DepthPeel && plan.Features.Silhouette, "depth peeling: silhouettes");
}

void TestSceneDepth()
{
  const psi::Settings s = Settings();
  PsiSceneFacts facts = Facts();
  facts.Parallel = true;
  PSI_CHECK(!PlanFrame(s, facts).Features.ExactSegments, "parallel: screen-linear is exact");
  facts = Facts();
  PSI_CHECK(PlanFrame(s, facts).Features.ExactSegments, "perspective: exact segments");
  facts.SceneOpaque = true;
  PsiFramePlan plan = PlanFrame(s, facts);
  PSI_CHECK(plan.SceneDepth && !plan.Features.OpaqueClip, "opaque geometry away from the volume");
  facts = Facts();
  facts.NearPlaneCuts = true;
  plan = PlanFrame(s, facts);
  PSI_CHECK(plan.SceneDepth && plan.Features.NearClip, "the near plane cuts the mesh");
  facts = Facts();
  facts.OpaqueOverlaps = facts.SceneOpaque = true;
  plan = PlanFrame(s, facts);
  PSI_CHECK(plan.SceneDepth && plan.Features.OpaqueClip, "opaque geometry inside the volume");
}
void TestEarlyRayTermination()
{
  // the bound on a ray's opacity: 1 - exp(-max tau * length), from the table's attenuation
  psi::TransferFunctionTable table;
  table.Size = 3;
  table.Rgba = { 1, 1, 1, 0.1f, 1, 1, 1, 0.5f, 1, 1, 1, 0.2f };
  PSI_CHECK(std::abs(psi::MaxRayOpacity(table, 4.0) - (1 - std::exp(-2.0))) < 1e-6,
    "MaxRayOpacity %g", psi::MaxRayOpacity(table, 4.0));
  PSI_CHECK(psi::MaxRayOpacity(table, 0.0) == 0, "a ray of no length stays transparent");

  using ERT = psi::EarlyRayTerminations;
  psi::Settings s = Settings();
  PsiSceneFacts facts = Facts();
  facts.MaxRayOpacity = 1 - std::exp(-20.0);
  PsiFramePlan plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Way.FrontToBack && plan.Open.Direction && plan.Open.MasksPerFrame,
    "a volume that can turn opaque: front to back, back to front timed against it");
  facts.MaxRayOpacity = psi::SaturatedOpacity - 1e-6;
  plan = PlanFrame(s, facts);
  PSI_CHECK(!plan.Way.FrontToBack && !plan.Open.Direction && !plan.Open.MasksPerFrame,
    "no pixel can turn opaque: back to front, nothing to time");
  s.EarlyRayTermination = ERT::On;
  plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Way.FrontToBack && !plan.Open.Direction && !plan.Open.MasksPerFrame,
    "'On': front to back all the same, with the default masks");
  s.EarlyRayTermination = ERT::Auto;
  s.IsosurfaceValues = { 0.5 };
  PSI_CHECK(PlanFrame(s, facts).Way.FrontToBack, "an isosurface can hide what is behind it");
  s.IsosurfaceOpacity = 0;
  PSI_CHECK(!PlanFrame(s, facts).Way.FrontToBack, "an isosurface of opacity 0 hides nothing");
  s = Settings();
  facts.MaxRayOpacity = 1;
  s.EarlyRayTermination = ERT::Off;
  plan = PlanFrame(s, facts);
  PSI_CHECK(!plan.Way.FrontToBack && !plan.Open.Direction, "switched off");
  for (ERT e : { ERT::On, ERT::Auto })
  {
    s.EarlyRayTermination = e;
    facts.DepthPeeled = true;
    plan = PlanFrame(s, facts);
    PSI_CHECK(!plan.Way.FrontToBack && !plan.Open.Any(), "not within depth peeling");
    facts.DepthPeeled = false;
    facts.MasksOpaquePixels = false;
    PSI_CHECK(!PlanFrame(s, facts).Way.FrontToBack, "not when the driver cannot mask pixels");
    facts.MasksOpaquePixels = true;
  }
}

// The projector and the decomposition: their 'Auto' is the geometry shader and the silhouette;
// the compute projector is timed against it where the driver has it, the fan never (not the
// silhouettes' image at isolated pixels).
void TestOpenWays()
{
  psi::Settings s; // every 'Auto'
  PsiSceneFacts facts = Facts();
  facts.ComputeAvailable = true;
  PsiFramePlan plan = PlanFrame(s, facts);
  PSI_CHECK(!plan.Way.ComputeProjector && plan.Features.Silhouette && plan.Open.Projector,
    "'Auto': geometry shader and silhouettes, the compute projector timed");
  facts.ComputeAvailable = false;
  PSI_CHECK(!PlanFrame(s, facts).Open.Projector, "no compute projector on this driver");
  s.Projector = psi::Projectors::ComputeShader;
  s.Decomposition = psi::Decompositions::Fan;
  plan = PlanFrame(s, facts);
  PSI_CHECK(plan.Way.ComputeProjector && !plan.Features.Silhouette && !plan.Open.Projector,
    "an explicit setting forces its way");
}
} // namespace

int main()
{
  TestMethodTables();
  TestEarlyDiscard();
  TestIsosurfaces();
  TestAdaptive();
  TestSeparateOpacityAndPeeling();
  TestSceneDepth();
  TestEarlyRayTermination();
  TestOpenWays();
  std::printf("%s: %d failures\n", psitest::Failures() ? "FAILED" : "passed", psitest::Failures());
  return psitest::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
