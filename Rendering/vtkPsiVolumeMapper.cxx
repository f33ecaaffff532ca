#include "vtkPsiVolumeMapper.h"
#include "vtkPsiVolumeMapperInternals.h"

#include "PsiAdaptiveNodes.h"
#include "PsiCellPointBounds.h"
#include "PsiComputeProjector.h"
#include "PsiDepthPeelingCalls.h"
#include "PsiFramePlan.h"
#include "PsiGeometryProjector.h"
#include "PsiIntegrationMethods.h"
#include "PsiMeshBuffers.h"
#include "PsiProjectionClasses.h"
#include "PsiRenderTarget.h"
#include "PsiSceneQueries.h"
#include "PsiShaderComposer.h"
#include "PsiShaderParameters.h"
#include "PsiStopwatch.h"
#include "PsiTableTextures.h"
#include "PsiTransferFunctionAnalysis.h"
#include "PsiTransferFunctionTable.h"
#include "PsiVisibilityOrder.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <functional>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPsiVolumeMapper);

vtkPsiVolumeMapper::vtkPsiVolumeMapper()
  : Impl(new Internals)
{
}

vtkPsiVolumeMapper::~vtkPsiVolumeMapper() = default;

void vtkPsiVolumeMapper::SetSettings(const psi::Settings& settings)
{
  for (const psi::SettingInfo& info : psi::SettingTable())
  {
    if (!info.Interaction)
    {
      this->SetRanged(info.Id, psi::ValueOf(settings, info.Id));
    }
  }
  this->SetIsosurfaceColor(
    settings.IsosurfaceColor[0], settings.IsosurfaceColor[1], settings.IsosurfaceColor[2]);
  this->SetIsosurfaceValues(settings.IsosurfaceValues);
  this->SetIsosurfaceOpacities(settings.IsosurfaceOpacities);
}

// The one clamp of a setting, with its one warning (psi::Change).
void vtkPsiVolumeMapper::SetRanged(psi::Setting id, double value)
{
  const psi::SettingChange change = psi::Change(this->Settings, id, value);
  if (!change.Warning.empty())
  {
    vtkWarningMacro(<< change.Warning);
  }
  if (change.Changed)
  {
    if (id == psi::Setting::IsosurfaceOpacity)
    {
      this->UpdateIsosurfaceList();
    }
    this->Modified();
  }
}

const char* vtkPsiVolumeMapper::GetIntegrationMethodName(int method)
{
  const psi::IntegrationMethodInfo* info = psi::FindIntegrationMethod(method);
  return info ? info->Name : "Unknown";
}

void vtkPsiVolumeMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Impl->Release(win);
  this->Superclass::ReleaseGraphicsResources(win);
}

double* vtkPsiVolumeMapper::GetBounds()
{
  vtkDataSet* input = this->GetDataSetInput();
  Internals& I = *this->Impl;
  if (I.Given) // several volumes intermixed: the world bounds of their mesh
  {
    const psi::TetMesh& m = I.Given->Mesh;
    for (int k = 0; k < 6; ++k)
    {
      this->Bounds[k] = m.Bounds[k] + m.Shift[k / 2];
    }
    return this->Bounds;
  }
  if (!input)
  {
    I.BoundsInput = nullptr;
    return this->Superclass::GetBounds();
  }
  if (input != I.BoundsInput || input->GetMTime() != I.BoundsTime)
  {
    if (!psi::CellPointBounds(input, this->Bounds))
    {
      input->GetBounds(this->Bounds);
    }
    I.BoundsInput = input;
    I.BoundsTime = input->GetMTime();
  }
  return this->Bounds;
}

// One frame: mesh, visibility order, the transfer function, the plan, the tables it reads,
// program, uniforms, draw and composite. Each stage's scope and time is logged at LogVerbosity.
void vtkPsiVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  vtkVLogScopeF(this->LogVerbosity, "Psi Volume: frame");
  const psi::Stopwatch clock;
  Internals& I = *this->Impl;
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkUnstructuredGridBase* input = this->GetInput();
  if (!renWin || (!input && !I.Given) || (!I.Given && this->RenderIntermixed(ren, vol)) ||
    I.Peeling.StageOf(this, vol) == PsiDepthPeelingCalls::Skip)
  {
    return;
  }
  I.Peeling.NoteTranslucentGeometry(this, ren);
  // an optical depth needs a positive unit distance: like 'Projected tetra', draw nothing
  const std::string badUnit = psi::UnitDistanceProblem(vol->GetProperty());
  if (badUnit != I.LastWarning && !badUnit.empty())
  {
    vtkWarningMacro(<< badUnit); // once per new value
  }
  I.LastWarning = badUnit;
  if (!badUnit.empty())
  {
    return this->ResetStatistics();
  }
  if (I.Context && I.Context != renWin)
  {
    I.Release(I.Context);
  }
  I.Context = renWin;
  if (I.Given)
  {
    this->UpdateGivenMesh();
  }
  if ((!I.Given && !this->UpdateMesh(vol, input)) || !this->UploadMesh(renWin))
  {
    return;
  }
  // (also after frames of several volumes intermixed, whose read-outs were the combined draw's)
  this->Stats.NumberOfTetrahedra = static_cast<vtkIdType>(I.Mesh.GetMesh().NumberOfTets());
  this->Stats.IntermixedVolumes = this->Stats.IntermixedTetrahedra = 0;
  const PsiFrameCamera cam = PsiFrameCamera::FromRenderer(ren, vol, I.Mesh.GetMesh().Shift);
  const PsiTableSources sources = this->UpdateTransferFunction(renWin, vol);
  const PsiFramePlan plan =
    this->ChooseWay(PlanFrame(this->Settings, this->SceneFacts(ren, vol, cam)), ren, cam);
  this->NotePlan(plan);
  const bool sorted = this->UpdateVisibilityOrder(input, cam, plan.Way.FrontToBack);
  const std::vector<PsiGpuTable*> tables = this->TablesOf(plan);
  this->UpdateTables(renWin, plan, tables, sources);
  if (I.Target.CaptureDepthTexture(
        ren, renWin, plan.Features.NearClip || plan.Features.OpaqueClip, plan.SceneDepth))
  {
    const psi::Stopwatch draw;
    this->TimeWay(draw, this->DrawVolume(renWin, ren, vol, cam, plan, tables));
  }
  I.Order.Finish();
  if (sorted)
  {
    this->Stats.LastSortSeconds = I.Order.GetLastSortSeconds();
    this->Stats.LastSortCycles = static_cast<vtkIdType>(I.Order.GetLastCycles());
  }
  const PsiDepthPeelingCalls::Stage stage = I.Peeling.GetStage();
  this->Stats.LastRenderSeconds = this->Frame.Add(clock.Seconds(),
    stage == PsiDepthPeelingCalls::Plain || stage == PsiDepthPeelingCalls::OutsideLayers);
  if (!psi::IsInteractiveRender(renWin))
  {
    this->LastStillSeconds = this->Stats.LastRenderSeconds;
  }
}

// Starts sorting on a worker thread when the view, the mesh or the direction changed (the draw
// streams the chunks as the sort emits them; the tables are updated meanwhile). True when a sort
// started.
bool vtkPsiVolumeMapper::UpdateVisibilityOrder(
  vtkUnstructuredGridBase* input, const PsiFrameCamera& cam, bool frontToBack)
{
  Internals& I = *this->Impl;
  const psi::Sorts method = this->Settings.SortMethod;
  const psi::SortDirection direction =
    frontToBack ? psi::SortDirection::NearestFirst : psi::SortDirection::FarthestFirst;
  if (!I.Order.NeedsUpdate(I.Mesh.GetVersion(), method, cam.MCVC, cam.Parallel, direction))
  {
    return false;
  }
  vtkVLogScopeF(this->LogVerbosity, "Psi Volume: visibility order");
  std::vector<int32_t> neighbors;
  if (method == psi::Sorts::MPVONC && I.Order.NeedsMesh(I.Mesh.GetVersion(), method) && I.Given)
  {
    neighbors = I.Given->Neighbors;
  }
  else if (method == psi::Sorts::MPVONC && I.Order.NeedsMesh(I.Mesh.GetVersion(), method))
  {
    psi::FaceNeighborsFromArray(I.Mesh.GetMesh(),
      input->GetCellData() ? input->GetCellData()->GetArray("FaceNeighbors") : nullptr,
      input->GetNumberOfCells(), neighbors);
  }
  I.Order.Update(I.Mesh.GetMesh(), I.Mesh.GetVersion(), std::move(neighbors), method, cam.MCVC,
    cam.Parallel, direction);
  return true;
}

// Projects and draws the volume with the chosen projector: the geometry-shader program, or the
// compute projector's projection pass and draw program. Returns the seconds spent making the
// programs ready (not the way's cost, TimeWay), or -1 when nothing was drawn.
double vtkPsiVolumeMapper::DrawVolume(vtkOpenGLRenderWindow* renWin, vtkRenderer* ren,
  vtkVolume* vol, const PsiFrameCamera& cam, const PsiFramePlan& plan,
  const std::vector<PsiGpuTable*>& tables)
{
  vtkVLogScopeF(this->LogVerbosity, "Psi Volume: draw");
  Internals& I = *this->Impl;
  const psi::ShaderFeatures& features = plan.Features;
  const bool gradients = plan.Tables.Gradients;
  const psi::Stopwatch ready;
  const bool compute = PsiComputeProjector::Chosen(plan.Way.ComputeProjector, renWin);
  this->LastUsedProjector =
    static_cast<int>(compute ? psi::Projectors::ComputeShader : psi::Projectors::GeometryShader);
  vtkShaderProgram* program = this->ReadyProjection(renWin, features, compute);
  if (!program)
  {
    return -1;
  }
  this->SetShaderParameters(program, ren, vol, cam, plan, tables);
  I.Mesh.Activate(program, gradients);
  vtkShaderProgram* draw = compute ? I.Compute.ReadyDrawProgram(renWin) : program;
  const double programSeconds = draw ? ready.Seconds() : -1;
  if (draw && compute)
  {
    this->SetShaderParameters(draw, ren, vol, cam, plan, tables);
    I.Mesh.Activate(draw, gradients); // the fragment shader reads points when clipping
  }
  if (draw)
  {
    std::string drawError;
    I.SamplesPassed = 0;
    auto drawImage = [&](int image)
    { this->DrawImage(renWin, vol, plan, draw, compute, image, drawError); };
    I.Target.DrawAndComposite(
      renWin, drawImage, I.Peeling.GetStage(),
      [&](vtkShaderProgram* composite)
      { I.Peeling.SetShaderParameters(composite, this, vol, renWin); },
      plan.Way.FrontToBack);
    I.Peeling.Deactivate();
    if (!drawError.empty() && drawError != I.LastDrawError && !plan.Trial)
    {
      vtkErrorMacro("Psi Volume: " << drawError); // an alternative being timed just loses
    }
    I.LastDrawError = plan.Trial ? I.LastDrawError : drawError;
  }
  I.Mesh.Deactivate();
  psi::DeactivateTables(tables);
  return programSeconds;
}

// One image of the frame (two within depth peeling, `image` naming the interval): the
// projector's draw of the visibility order, front to back with the opaque pixels masked between
// its chunks (PsiOpacityMasks); the samples that pass counted when asked (SetCountSamplesPassed).
void vtkPsiVolumeMapper::DrawImage(vtkOpenGLRenderWindow* renWin, vtkVolume* vol,
  const PsiFramePlan& plan, vtkShaderProgram* draw, bool compute, int image, std::string& error)
{
  Internals& I = *this->Impl;
  if (plan.Features.DepthPeel)
  {
    renWin->GetShaderCache()->ReadyShaderProgram(draw); // the fragment shader's program
    draw->SetUniformi("peelStage", I.Peeling.GetStage());
    draw->SetUniformi("peelRange", image);
    I.Peeling.SetShaderParameters(draw, this, vol, renWin);
  }
  const size_t pixels = size_t(I.Target.GetSize()[0]) * size_t(I.Target.GetSize()[1]);
  std::function<void(size_t)> mask;
  if (plan.Way.FrontToBack)
  {
    I.Masks.Begin(I.Target.GetImage(), I.Order.GetSize(),
      PsiVisibilityOrder::ChunkTetsFor(I.Order.GetSize(), pixels), plan.Way.MasksPerFrame);
    mask = [&](size_t first)
    {
      if (I.Masks.IsDue(first))
      {
        I.StopCounting();
        I.Masks.Mask(first, renWin, compute ? nullptr : draw);
        I.StartCounting();
      }
    };
  }
  I.StartCounting();
  if (compute)
  {
    I.Compute.Draw(renWin, I.Order, pixels, I.Limits().MaxStorageBlockBytes, error, mask);
  }
  else
  {
    I.Geometry.Draw(I.Order, draw, pixels, mask);
  }
  I.StopCounting();
  I.Masks.End();
}

// Gathers and uploads the mesh when the data or the array changed. False: nothing to draw.
bool vtkPsiVolumeMapper::UpdateMesh(vtkVolume* vol, vtkUnstructuredGridBase* input)
{
  Internals& I = *this->Impl;
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(
    input, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (input->GetNumberOfCells() == 0)
  {
    this->ResetStatistics();
    return false; // nothing to draw; an empty grid is not an error
  }
  if (!scalars)
  {
    vtkErrorMacro("Psi Volume needs a scalar array to color by: choose a point or cell array "
                  "(Coloring) for this representation.");
    return false;
  }
  const psi::ScalarComponent component =
    psi::ColorMapComponent(vol->GetProperty(), scalars->GetNumberOfComponents());
  const std::string arrayKey = std::string(scalars->GetName() ? scalars->GetName() : "") + "|" +
    std::to_string(cellFlag) + "|" + std::to_string(this->ScalarMode) + "|" +
    std::to_string(component.Index) + "|" + std::to_string(component.Opacity);
  const PsiMeshBuffers::Change change = I.Mesh.NeedsUpdate(input, scalars, arrayKey);
  if (change == PsiMeshBuffers::Change::None ||
    (change == PsiMeshBuffers::Change::Scalars && I.Mesh.UpdateScalars(scalars, component)))
  {
    return true;
  }
  vtkVLogScopeF(this->LogVerbosity, "Psi Volume: mesh");
  I.Mesh.Update(input, scalars, cellFlag == 1, component, arrayKey);
  const psi::TetMesh& mesh = I.Mesh.GetMesh();
  this->Stats.NumberOfSkippedCells = mesh.NonTetCells + mesh.NonFiniteTets;
  this->Stats.NumberOfTetrahedra = static_cast<vtkIdType>(mesh.NumberOfTets());
  const std::string skipped = psi::DescribeSkippedCells(mesh);
  if (!skipped.empty())
  {
    vtkWarningMacro("Psi Volume " << skipped);
  }
  return true;
}

// The mesh on the GPU (when it changed since). False: nothing to draw (none, or more points than
// the driver's texture buffers hold: said once, the mesh emptied).
bool vtkPsiVolumeMapper::UploadMesh(vtkOpenGLRenderWindow* renWin)
{
  Internals& I = *this->Impl;
  std::string error;
  if (!I.Mesh.Upload(renWin, I.Limits().MaxTextureBufferTexels, error))
  {
    vtkErrorMacro("Psi Volume: " << error);
    this->Stats.NumberOfTetrahedra = 0;
  }
  return I.Mesh.GetMesh().NumberOfTets() > 0;
}

// The projection program of this frame's projector for these features (each projector composes
// and builds a program once per feature set).
vtkShaderProgram* vtkPsiVolumeMapper::ReadyProjection(
  vtkOpenGLRenderWindow* renWin, const psi::ShaderFeatures& features, bool compute)
{
  Internals& I = *this->Impl;
  this->LastFeatureDefines = features.Defines();
  const char* integrator = psi::IntegratorSource(features.Method);
  std::string error = "the shader program failed to compile (see above).";
  bool built = false;
  vtkShaderProgram* program = !integrator ? nullptr
    : compute ? I.Compute.ReadyComputeProgram(features, integrator, error, built)
              : I.Geometry.ReadyProgram(renWin, features, integrator, built);
  if (!program)
  {
    vtkErrorMacro(
      "Psi Volume: " << (integrator ? error
                                    : std::string("no GLSL integrator ") +
            psi::GetIntegrationMethodInfo(features.Method).GlslName + ".glsl embedded."));
  }
  return program;
}

void vtkPsiVolumeMapper::SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren,
  vtkVolume* vol, const PsiFrameCamera& cam, const PsiFramePlan& plan,
  const std::vector<PsiGpuTable*>& tables)
{
  const psi::ShaderFeatures& f = plan.Features;
  Internals& I = *this->Impl;
  vtkVolumeProperty* property = vol->GetProperty();
  SetCameraShaderParameters(program, cam);
  program->SetUniform1iv("classTable", 81, psi::GetPackedProjectionClassTable().data());
  program->SetUniformf("unitDistance", static_cast<float>(psi::OpacityUnitDistance(property)));
  psi::ActivateTables(tables, program); // the adaptive nodes among them, when drawn
  I.Target.SetShaderParameters(program);
  if (f.Silhouette)
  {
    SetPixelRayShaderParameters(program, cam, I.Target.GetSize());
    SetSilhouetteShaderParameters(program, I.Target.GetSize());
  }
  if (f.IsoCount > 0)
  {
    const psi::Settings& s = this->Settings;
    PsiIsosurfaceStyle style;
    style.UseColorMap = s.IsosurfaceUseColorMap;
    std::copy(s.IsosurfaceColor, s.IsosurfaceColor + 3, style.Color);
    style.Lighting = s.IsosurfaceShading != psi::IsosurfaceShadings::Unlit;
    style.Smooth = f.IsoSmooth;
    style.MaxLights = f.MaxLights;
    style.ValueColors = I.Given ? &I.Given->IsoColors : nullptr;
    SetIsosurfaceShaderParameters(
      program, this->Isosurfaces, I.Mesh.GetMesh().ScalarRange, style, property, ren, cam);
    if (f.IsoTriangles)
    {
      // a cell's pieces and surfaces in the order the frame composites (PsiIsoTrianglesGS.glsl)
      program->SetUniformi("nearestFirst", plan.Way.FrontToBack ? 1 : 0);
    }
  }
}

int vtkPsiVolumeMapper::GetMeshVersion() const
{
  return this->Impl->Mesh.GetVersion();
}

void vtkPsiVolumeMapper::SetRecordDrawOrder(bool on)
{
  this->Impl->Order.SetRecordDrawn(on);
}

void vtkPsiVolumeMapper::SetDriverLimitsForTesting(
  long long maxTextureBufferTexels, long long maxStorageBlockBytes)
{
  this->Impl->TestingLimits.MaxTextureBufferTexels = maxTextureBufferTexels;
  this->Impl->TestingLimits.MaxStorageBlockBytes = maxStorageBlockBytes;
  this->Modified();
}

void vtkPsiVolumeMapper::SetCountSamplesPassed(bool on)
{
  this->Impl->CountSamples = on;
}

vtkIdType vtkPsiVolumeMapper::GetLastSamplesPassed() const
{
  return static_cast<vtkIdType>(this->Impl->SamplesPassed);
}

const std::vector<uint32_t>& vtkPsiVolumeMapper::GetLastDrawOrder() const
{
  return this->Impl->Order.GetDrawn();
}

void vtkPsiVolumeMapper::ResetStatistics()
{
  const double pre = this->Stats.LastPreIntegrationSeconds;
  this->Stats = psi::FrameStats();
  this->Stats.LastPreIntegrationSeconds = pre;
}

void vtkPsiVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const psi::SettingInfo& info : psi::SettingTable())
  {
    if (!info.Interaction)
    {
      os << indent << info.Name << ": " << psi::ValueOf(this->Settings, info.Id) << "\n";
    }
  }
  os << indent << "NumberOfTetrahedra: " << this->Stats.NumberOfTetrahedra << "\n";
  os << indent << "NumberOfSkippedCells: " << this->Stats.NumberOfSkippedCells << "\n";
}
