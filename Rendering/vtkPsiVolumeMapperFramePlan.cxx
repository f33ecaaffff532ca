// vtkPsiVolumeMapper's side of the frame plan (PsiFramePlan.h): the transfer function sampled
// first (every method reads it, and its zero regions and nodes are facts of the scene), the
// settings and the facts handed to psi's PlanFrame, what the last frame used, and then only the
// tables the plan names. The rest of the mapper is in vtkPsiVolumeMapper.cxx.
#include "vtkPsiVolumeMapper.h"
#include "vtkPsiVolumeMapperInternals.h"

#include "PsiFramePlan.h"
#include "PsiOpacityMasks.h"
#include "PsiSceneQueries.h"
#include "PsiShaderComposer.h"
#include "PsiShaderParameters.h"
#include "PsiStopwatch.h"
#include "PsiTransferFunctionAnalysis.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
// The feature defines of a plan on one line of the log.
std::string OneLine(std::string defines)
{
  for (char& c : defines)
  {
    c = c == '\n' ? ' ' : c;
  }
  return defines;
}
} // namespace

// The sampled transfer function, and the adaptive nodes when adaptive sampling may be used.
PsiTableSources vtkPsiVolumeMapper::UpdateTransferFunction(
  vtkOpenGLRenderWindow* renWin, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  const psi::TetMesh& mesh = I.Mesh.GetMesh();
  PsiTableSources in;
  in.Property = vol->GetProperty();
  in.ScalarRange = mesh.ScalarRange;
  // with a separate opacity array the attenuation is sampled over the opacity scalars' range
  in.OpacityRange = mesh.Opacity.empty() ? nullptr : mesh.OpacityRange;
  in.Samples = this->Settings.TransferFunctionSamples;
  in.Transfer = &I.Tables.Transfer;
  in.LengthAxis = psi::MakePreIntegrationLengthAxis(mesh.MinEdgeLength, mesh.MaxEdgeLength);
  in.MaxNodes = psi::MaxAdaptiveNodes;
  in.NodeTolerance = psi::AdaptiveNodeTolerance;
  if (I.Given) // several volumes intermixed: their tables and nodes as one
  {
    in.Table = &I.Given->Table;
    in.OpacityPrefix = &I.Given->OpacityPrefix;
    in.ZeroOpacity = I.Given->ZeroOpacity;
    I.AdaptiveNodes.UseNodes(I.Given->Nodes, I.Given->TableDeviation, in.NodeTolerance);
  }
  std::vector<PsiGpuTable*> first{ &I.Tables.Transfer };
  if (NeedsAdaptiveNodes(this->Settings) && !I.Given)
  {
    first.push_back(&I.AdaptiveNodes);
  }
  psi::UpdateTables(first, renWin, in);
  return in;
}

// Everything the plan needs to know, asked here: the camera, the other props, the depth-peeling
// stage, the data, the sampled function, and the driver's geometry-shader limits.
PsiSceneFacts vtkPsiVolumeMapper::SceneFacts(
  vtkRenderer* ren, vtkVolume* vol, const PsiFrameCamera& cam)
{
  Internals& I = *this->Impl;
  PsiSceneFacts facts;
  facts.Parallel = cam.Parallel;
  facts.NearPlaneCuts = cam.NearPlaneCuts(I.Mesh.GetMesh().Bounds);
  facts.OpaqueOverlaps = psi::OpaqueGeometryOverlaps(ren, vol);
  facts.SceneOpaque = facts.OpaqueOverlaps || psi::SceneHasOpaqueGeometry(ren);
  facts.DepthPeeled = I.Peeling.GetStage() > PsiDepthPeelingCalls::Plain;
  facts.SeparateOpacity = !I.Mesh.GetMesh().Opacity.empty();
  facts.ZeroOpacity = I.Tables.Transfer.HasZeroOpacity();
  facts.NodesFaithful = I.AdaptiveNodes.IsFaithful();
  facts.TableDeviation = I.AdaptiveNodes.GetTableDeviation();
  const double* b = vol->GetBounds(); // a ray's longest path through the volume, in world units
  facts.MaxRayOpacity = psi::MaxRayOpacity(I.Tables.Transfer.GetTable(),
    std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
      (b[5] - b[4]) * (b[5] - b[4])));
  facts.MasksOpaquePixels = PsiOpacityMasks::IsSupported();
  facts.ComputeAvailable =
    PsiComputeProjector::IsSupported(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()));
  if (MayUseIsoTriangles(this->Settings, facts))
  {
    int vertices = 0, components = 0;
    glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES, &vertices);
    glGetIntegerv(GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS, &components);
    facts.GeometryOutputFits = [vertices, components](const psi::ShaderFeatures& f)
    { return psi::FitsGeometryOutputLimits(f, vertices, components); };
  }
  return facts;
}

// What the last frame used (the getters' read-outs), and the one warning a plan may carry.
void vtkPsiVolumeMapper::NotePlan(const PsiFramePlan& plan)
{
  Internals& I = *this->Impl;
  const psi::ShaderFeatures& f = plan.Features;
  vtkVLogF(this->LogVerbosity, "Psi Volume: plan %s", OneLine(f.Key()).c_str());
  this->LastUsedNearPlaneClipping = f.NearClip;
  this->LastUsedOpaqueClipping = f.OpaqueClip;
  this->LastUsedIsosurfaceMethod = f.IsoCount == 0
    ? -1
    : static_cast<int>(f.IsoTriangles ? psi::IsosurfaceMethods::MarchingTetrahedra
                                      : psi::IsosurfaceMethods::PerFragment);
  this->LastUsedEarlyDiscard = f.EarlyDiscard;
  this->LastUsedEarlyRayTermination = plan.Way.FrontToBack;
  this->LastUsedDecomposition =
    static_cast<int>(f.Silhouette ? psi::Decompositions::Silhouette : psi::Decompositions::Fan);
  this->LastUsedMasksPerFrame = plan.Way.FrontToBack ? plan.Way.MasksPerFrame : 0;
  this->Stats.DrawWay = plan.Way.Describe() + (f.Silhouette ? ", silhouettes" : ", fan") + " (" +
    I.Choice.Describe() + ")";
  this->LastUsedAdaptiveSampling = f.Adaptive;
  this->LastNumberOfAdaptiveNodes = f.Adaptive ? I.AdaptiveNodes.Size() : 0;
  const std::string note = plan.MethodReplaced
    ? "Psi Volume: full pre-integration tabulates one scalar for color and opacity; with a "
      "separate opacity array it draws with partial pre-integration."
    : "";
  if (!note.empty() && note != I.LastFeatureNote)
  {
    vtkWarningMacro(<< note);
  }
  I.LastFeatureNote = note;
}

// The way this frame draws (PsiMeasuredChoice.h): the plan's, or where a setting is 'Auto' the
// way being timed or the fastest timed. What decides which way is fastest: the mesh (not its
// values: a time step on the same mesh keeps the choice, unless its range changes the sampled
// transfer function), the sampled transfer function, the settings (the mapper's modification
// time), the view's size, the features the scene calls for, and the volume's projected size.
PsiFramePlan vtkPsiVolumeMapper::ChooseWay(
  const PsiFramePlan& plan, vtkRenderer* ren, const PsiFrameCamera& cam)
{
  Internals& I = *this->Impl;
  const int* size = ren->GetSize();
  const std::string decides = std::to_string(I.Mesh.GetVersion()) + " " +
    std::to_string(I.Tables.Transfer.GetVersion()) + " " + std::to_string(this->GetMTime()) + " " +
    std::to_string(size[0]) + "x" + std::to_string(size[1]) + " " + plan.Features.Key();
  const double pixels = double(size[0]) * double(size[1]) *
    psi::ProjectedFraction(I.Mesh.GetMesh().Bounds, cam.MCVC, cam.VCDC);
  PsiFramePlan chosen = plan;
  chosen.Way = I.Choice.Next(decides, pixels, plan.Way, plan.Open);
  chosen.Trial = I.Choice.IsMeasuring() && chosen.Way != plan.Way; // a chosen way's errors are said
  return chosen;
}

// The frame's time for the way it drew, while ways are timed: from `draw`'s start to the end of
// the GL work (waited for), less `programSeconds` spent building programs (DrawVolume); a way
// that drew nothing (-1) never wins.
void vtkPsiVolumeMapper::TimeWay(const psi::Stopwatch& draw, double programSeconds)
{
  Internals& I = *this->Impl;
  if (I.Choice.IsMeasuring())
  {
    glFinish();
    I.Choice.Record(programSeconds < 0 ? std::numeric_limits<double>::infinity()
                                       : draw.Seconds() - programSeconds);
  }
}

// The tables the plan's features read, in the order they are bound.
std::vector<PsiGpuTable*> vtkPsiVolumeMapper::TablesOf(const PsiFramePlan& plan)
{
  Internals& I = *this->Impl;
  std::vector<PsiGpuTable*> tables{ &I.Tables.Transfer };
  if (plan.Tables.OpacityPrefix)
  {
    tables.push_back(&I.Tables.OpacityPrefix);
  }
  if (plan.Tables.PartialPreIntegrationTable)
  {
    tables.push_back(&I.Tables.PartialPreIntegrationTable);
  }
  if (plan.Tables.PreIntegration)
  {
    tables.push_back(&I.Tables.PreIntegration);
  }
  if (plan.Tables.AdaptiveNodes)
  {
    tables.push_back(&I.AdaptiveNodes);
  }
  return tables;
}

// Only the tables the plan names, `tables` (TablesOf), and the mesh's smoothed gradients when
// it asks for them.
void vtkPsiVolumeMapper::UpdateTables(vtkOpenGLRenderWindow* renWin, const PsiFramePlan& plan,
  const std::vector<PsiGpuTable*>& tables, const PsiTableSources& sources)
{
  vtkVLogScopeF(this->LogVerbosity, "Psi Volume: tables");
  Internals& I = *this->Impl;
  psi::UpdateTables(tables, renWin, sources);
  if (plan.Tables.PreIntegration)
  {
    // Röttger's table belongs to one transfer function: rebuilt on every edit (timed)
    this->Stats.LastPreIntegrationSeconds = I.Tables.PreIntegration.GetLastBuildSeconds();
  }
  if (plan.Tables.Gradients)
  {
    I.Mesh.UpdateGradients(renWin);
  }
}
