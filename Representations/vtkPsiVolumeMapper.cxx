#include "vtkPsiVolumeMapper.h"

#include "PsiAdaptiveNodes.h"
#include "PsiComputeProjector.h"
#include "PsiDepthPeelingCalls.h"
#include "PsiGeometryProjector.h"
#include "PsiIntegrationMethods.h"
#include "PsiMeshBuffers.h"
#include "PsiProjectionClasses.h"
#include "PsiRenderTarget.h"
#include "PsiShaderComposer.h"
#include "PsiShaderParameters.h"
#include "PsiTransferFunctionAnalysis.h"
#include "PsiTransferFunctionTable.h"
#include "PsiTransferTextures.h"
#include "PsiVisibilityOrder.h"

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
#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides

#include <algorithm>
#include <array>
#include <chrono>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

const psi::IntegrationMethodInfo& MethodInfo(int method)
{
  return psi::GetIntegrationMethodInfo(static_cast<psi::Method>(method));
}
} // namespace

struct vtkPsiVolumeMapper::Internals
{
  PsiMeshBuffers Mesh;
  PsiVisibilityOrder Order;
  PsiTransferTables Tables;
  PsiRenderTarget Target;
  PsiGeometryProjector Geometry;
  PsiComputeProjector Compute;
  PsiDepthPeelingCalls Peeling; // the depth-peeling stage of this call

  // Transfer-function nodes for adaptive sampling, for the property and range they came from.
  PsiAdaptiveNodes AdaptiveNodes;

  std::string LastWarning;
  std::string LastFeatureNote; // what a separate opacity array changed, said once
  vtkWindow* Context = nullptr;

  void Release(vtkWindow* win)
  {
    if (this->Context)
    {
      this->Mesh.ReleaseGraphicsResources(win);
      this->Order.ReleaseGraphicsResources(win);
    }
    this->Tables.ReleaseGraphicsResources(win);
    this->Peeling.ReleaseGraphicsResources(win);
    this->Target.ReleaseGraphicsResources(win);
    this->Geometry.ReleaseGraphicsResources();
    this->Compute.ReleaseGraphicsResources(win);
    this->Context = nullptr;
  }
};

vtkStandardNewMacro(vtkPsiVolumeMapper);

vtkPsiVolumeMapper::vtkPsiVolumeMapper()
  : Impl(new Internals)
{
}

vtkPsiVolumeMapper::~vtkPsiVolumeMapper() = default;

void vtkPsiVolumeMapper::SetIntegrationMethod(int method)
{
  method = std::min(std::max(method, 0), psi::NumberOfIntegrationMethods() - 1);
  if (method != this->IntegrationMethod)
  {
    this->IntegrationMethod = method;
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

// One frame: mesh, visibility order, tables, program, uniforms, draw and composite.
void vtkPsiVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  const auto t0 = Clock::now();
  Internals& I = *this->Impl;
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkUnstructuredGridBase* input = this->GetInput();
  if (!renWin || !input || I.Peeling.StageOf(this, vol) == PsiDepthPeelingCalls::Skip)
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
  if (!this->UpdateMesh(renWin, vol, input) || I.Mesh.GetMesh().NumberOfTets() == 0)
  {
    return;
  }
  const PsiFrameCamera cam = PsiFrameCamera::FromRenderer(ren, vol, I.Mesh.GetMesh().Shift);
  bool sorted = false;
  if (I.Order.NeedsUpdate(I.Mesh.GetVersion(), this->SortMethod, cam.MCVC, cam.Parallel))
  {
    std::vector<int32_t> neighbors;
    if (this->SortMethod == MPVONC && I.Order.NeedsMesh(I.Mesh.GetVersion(), this->SortMethod))
    {
      psi::FaceNeighborsFromArray(I.Mesh.GetMesh(),
        input->GetCellData() ? input->GetCellData()->GetArray("FaceNeighbors") : nullptr,
        input->GetNumberOfCells(), neighbors);
    }
    I.Order.Update(I.Mesh.GetMesh(), I.Mesh.GetVersion(), std::move(neighbors),
      this->SortMethod, cam.MCVC, cam.Parallel); // sorts while the frame draws
    sorted = true;
  }
  this->UpdateTables(renWin, vol);
  const psi::ShaderFeatures features = this->ChooseFeatures(ren, vol, cam);
  if (I.Target.CaptureDepthTexture(ren, renWin, features.NearClip || features.OpaqueClip))
  {
    this->DrawVolume(renWin, ren, vol, cam, features);
  }
  I.Order.Finish();
  if (sorted)
  {
    this->Stats.LastSortSeconds = I.Order.GetLastSortSeconds();
    this->Stats.LastSortCycles = static_cast<vtkIdType>(I.Order.GetLastCycles());
  }
  this->Stats.LastRenderSeconds = SecondsSince(t0);
}

// Projects and draws the volume with the chosen projector: the geometry-shader program, or the
// compute projector's projection pass and draw program.
void vtkPsiVolumeMapper::DrawVolume(vtkOpenGLRenderWindow* renWin, vtkRenderer* ren,
  vtkVolume* vol, const PsiFrameCamera& cam, const psi::ShaderFeatures& features)
{
  Internals& I = *this->Impl;
  const bool gradients = features.IsoCount > 0 && features.IsoSmooth;
  const bool compute = PsiComputeProjector::Chosen(this->Projector, renWin);
  this->LastUsedProjector = compute ? PROJECTOR_COMPUTE_SHADER : PROJECTOR_GEOMETRY_SHADER;
  vtkShaderProgram* program = this->ReadyProjection(renWin, features, compute);
  if (!program)
  {
    return;
  }
  this->SetShaderParameters(program, ren, vol, cam, features);
  I.Mesh.Activate(program, gradients);
  vtkShaderProgram* draw = compute ? I.Compute.ReadyDrawProgram(renWin) : program;
  if (draw && compute)
  {
    this->SetShaderParameters(draw, ren, vol, cam, features);
    I.Mesh.Activate(draw, gradients); // the fragment shader reads points when clipping
  }
  if (draw)
  {
    const size_t pixels = size_t(I.Target.GetSize()[0]) * size_t(I.Target.GetSize()[1]);
    auto drawImage = [&](int image) {
      if (features.DepthPeel)
      {
        renWin->GetShaderCache()->ReadyShaderProgram(draw); // the fragment shader's program
        draw->SetUniformi("peelStage", I.Peeling.GetStage());
        draw->SetUniformi("peelRange", image);
        I.Peeling.SetShaderParameters(draw, this, vol, renWin);
      }
      if (compute)
      {
        I.Compute.Draw(renWin, I.Order, pixels);
      }
      else
      {
        I.Geometry.Draw(I.Order, draw, pixels);
      }
    };
    I.Target.DrawAndComposite(renWin, drawImage, I.Peeling.GetStage(),
      [&](vtkShaderProgram* composite) {
        I.Peeling.SetShaderParameters(composite, this, vol, renWin);
      });
    I.Peeling.Deactivate();
  }
  I.Mesh.Deactivate();
  this->DeactivateTables(features);
}

// Gathers and uploads the mesh when the data or the array changed. False: nothing to draw.
bool vtkPsiVolumeMapper::UpdateMesh(
  vtkOpenGLRenderWindow* renWin, vtkVolume* vol, vtkUnstructuredGridBase* input)
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
    (change == PsiMeshBuffers::Change::Scalars &&
      I.Mesh.UpdateScalars(renWin, scalars, component)))
  {
    return true;
  }
  std::string error;
  if (!I.Mesh.Update(renWin, input, scalars, cellFlag == 1, component, arrayKey, error))
  {
    vtkErrorMacro("Psi Volume: " << error);
  }
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

// The transfer-function table, and only the other tables the frame's features need.
void vtkPsiVolumeMapper::UpdateTables(vtkOpenGLRenderWindow* renWin, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  vtkVolumeProperty* property = vol->GetProperty();
  const psi::TetMesh& mesh = I.Mesh.GetMesh();
  // with a separate opacity array the attenuation is sampled over the opacity scalars' range
  const double* opacityRange = mesh.Opacity.empty() ? nullptr : mesh.OpacityRange;
  const int samples = this->TransferFunctionSamples;
  if (I.Tables.Transfer.NeedsUpdate(property, mesh.ScalarRange, samples, opacityRange))
  {
    I.Tables.Transfer.Update(renWin, property, mesh.ScalarRange, samples, opacityRange);
  }
  if (this->EarlyDiscard && I.Tables.Transfer.HasZeroOpacity() &&
    I.Tables.OpacityPrefix.NeedsUpdate(I.Tables.Transfer.GetVersion()))
  {
    I.Tables.OpacityPrefix.Update(renWin, I.Tables.Transfer);
  }
  const psi::IntegrationMethodInfo& method = MethodInfo(this->DrawnMethod());
  if (method.NeedsPsiTable && I.Tables.PsiTable.NeedsUpdate())
  {
    I.Tables.PsiTable.Update(renWin);
  }
  const psi::PreIntegrationLengthAxis axis =
    psi::MakePreIntegrationLengthAxis(mesh.MinEdgeLength, mesh.MaxEdgeLength);
  if (method.NeedsPreIntegrationTable &&
    I.Tables.PreIntegration.NeedsUpdate(I.Tables.Transfer.GetVersion(), axis))
  {
    // Röttger's table belongs to one transfer function: rebuilt on every edit (timed).
    this->Stats.LastPreIntegrationSeconds =
      I.Tables.PreIntegration.Update(renWin, I.Tables.Transfer, axis);
  }
  if (!this->Isosurfaces.Empty() && this->IsosurfaceShading == ISO_SMOOTH)
  {
    I.Mesh.UpdateGradients(renWin);
  }
  if (this->AdaptiveSampling != ADAPTIVE_OFF &&
    I.AdaptiveNodes.NeedsUpdate(property, mesh.ScalarRange, I.Tables.Transfer.GetVersion()))
  {
    I.AdaptiveNodes.Update(property, mesh.ScalarRange, I.Tables.Transfer.GetTable(),
      I.Tables.Transfer.GetVersion(), MaxAdaptiveNodes, AdaptiveNodeTolerance);
  }
}

// What the scene calls for: only these are composed into the program.
psi::ShaderFeatures vtkPsiVolumeMapper::ChooseFeatures(
  vtkRenderer* ren, vtkVolume* vol, const PsiFrameCamera& cam)
{
  Internals& I = *this->Impl;
  psi::ShaderFeatures f;
  f.Method = this->DrawnMethod();
  f.ExactSegments = !cam.Parallel && this->ExactPerspectiveSegments;
  // within depth peeling, the silhouettes' exact segments are clipped to the pass's intervals
  f.DepthPeel = I.Peeling.GetStage() > PsiDepthPeelingCalls::Plain;
  f.Silhouette = psi::SilhouetteChosen(this->Decomposition) || f.DepthPeel;
  f.NearClip = cam.NearPlaneCuts(I.Mesh.GetMesh().Bounds);
  f.OpaqueClip = PsiRenderTarget::OpaqueGeometryOverlaps(ren, vol);
  f.IsoCount = this->Isosurfaces.Count();
  f.IsoSmooth = f.IsoCount > 0 && this->IsosurfaceShading == ISO_SMOOTH;
  const bool zeroOpacity = I.Tables.Transfer.HasZeroOpacity();
  if (f.IsoCount > 0 &&
    (this->IsosurfaceMethod == ISO_MARCHING_TETRAHEDRA ||
      (this->IsosurfaceMethod == ISO_AUTO && this->EarlyDiscard && zeroOpacity)))
  {
    GLint maxVertices = 0, maxComponents = 0;
    glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES, &maxVertices);
    glGetIntegerv(GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS, &maxComponents);
    psi::ShaderFeatures withTriangles = f; // the budget of the marching-tetrahedra program
    withTriangles.IsoTriangles = true;
    f.IsoTriangles = psi::FitsGeometryOutputLimits(withTriangles, maxVertices, maxComponents);
  }
  // Early discard only when the opacity function has zero regions, and not with per-fragment
  // isosurfaces (visible where the volume is transparent; marching tetrahedra still emit the
  // surfaces of a cell whose volume pieces are dropped).
  f.EarlyDiscard = this->EarlyDiscard && zeroOpacity && (f.IsoCount == 0 || f.IsoTriangles);
  f.Adaptive = I.AdaptiveNodes.IsFaithful() &&
    (this->AdaptiveSampling == ADAPTIVE_ON ||
      (this->AdaptiveSampling == ADAPTIVE_AUTO &&
        I.AdaptiveNodes.GetTableDeviation() > AdaptiveAutoDeviation));
  f.MaxAdaptiveNodes = MaxAdaptiveNodes;
  this->ChooseSeparateOpacity(f);
  this->LastUsedNearPlaneClipping = f.NearClip;
  this->LastUsedOpaqueClipping = f.OpaqueClip;
  this->LastUsedIsosurfaceMethod =
    f.IsoCount == 0 ? -1 : f.IsoTriangles ? ISO_MARCHING_TETRAHEDRA : ISO_PER_FRAGMENT;
  this->LastUsedEarlyDiscard = f.EarlyDiscard;
  this->LastUsedAdaptiveSampling = f.Adaptive;
  this->LastNumberOfAdaptiveNodes = f.Adaptive ? I.AdaptiveNodes.Size() : 0;
  return f;
}

// The integration method drawn: the setting, except that Röttger's table tabulates one scalar for
// color and opacity, so that with a separate opacity array full pre-integration draws as partial
// pre-integration (the tables and the program both follow this).
int vtkPsiVolumeMapper::DrawnMethod() const
{
  const bool separate = !this->Impl->Mesh.GetMesh().Opacity.empty();
  return separate && MethodInfo(this->IntegrationMethod).NeedsPreIntegrationTable
    ? static_cast<int>(psi::Method::PartialPreIntegration)
    : this->IntegrationMethod;
}

// A separate opacity array: drawn with silhouettes, whose fragments carry both scalars; not with
// adaptive sampling (nodes of one scalar), nor Röttger's table (DrawnMethod); early discard
// judged on the opacity scalar, per cell.
void vtkPsiVolumeMapper::ChooseSeparateOpacity(psi::ShaderFeatures& f)
{
  Internals& I = *this->Impl;
  f.SeparateOpacity = !I.Mesh.GetMesh().Opacity.empty();
  std::string note;
  if (f.SeparateOpacity)
  {
    f.Silhouette = true;
    f.Adaptive = false;
    f.EarlyDiscard = f.EarlyDiscard && !f.IsoTriangles;
  }
  if (f.Method != this->IntegrationMethod)
  {
    note = "Psi Volume: full pre-integration tabulates one scalar for color and opacity; with "
           "a separate opacity array it draws with partial pre-integration.";
  }
  if (!note.empty() && note != I.LastFeatureNote)
  {
    vtkWarningMacro(<< note);
  }
  I.LastFeatureNote = note;
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
  this->NumberOfProgramBuilds += built ? 1 : 0;
  if (!program)
  {
    vtkErrorMacro("Psi Volume: " << (integrator ? error
                                                : std::string("no GLSL integrator ") +
                         MethodInfo(features.Method).GlslName + ".glsl embedded."));
  }
  return program;
}

void vtkPsiVolumeMapper::SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren,
  vtkVolume* vol, const PsiFrameCamera& cam, const psi::ShaderFeatures& f)
{
  Internals& I = *this->Impl;
  vtkVolumeProperty* property = vol->GetProperty();
  SetCameraShaderParameters(program, cam);
  program->SetUniform1iv("classTable", 81, psi::GetPackedProjectionClassTable().data());
  program->SetUniformf("unitDistance", static_cast<float>(psi::OpacityUnitDistance(property)));
  I.Tables.Activate(program, f.EarlyDiscard, MethodInfo(f.Method).NeedsPsiTable,
    MethodInfo(f.Method).NeedsPreIntegrationTable);
  I.Target.SetShaderParameters(program);
  if (f.Silhouette)
  {
    SetPixelRayShaderParameters(program, cam, I.Target.GetSize());
    SetSilhouetteShaderParameters(program, I.Target.GetSize());
  }
  if (f.IsoCount > 0)
  {
    PsiIsosurfaceStyle style;
    style.UseColorMap = this->IsosurfaceUseColorMap;
    std::copy(this->IsosurfaceColor, this->IsosurfaceColor + 3, style.Color);
    style.Lighting = this->IsosurfaceLighting;
    style.Smooth = f.IsoSmooth;
    style.MaxLights = f.MaxLights;
    SetIsosurfaceShaderParameters(
      program, this->Isosurfaces, I.Mesh.GetMesh().ScalarRange, style, property, ren, cam);
  }
  if (f.Adaptive)
  {
    I.AdaptiveNodes.Activate(program);
  }
}

void vtkPsiVolumeMapper::DeactivateTables(const psi::ShaderFeatures& f)
{
  this->Impl->Tables.Deactivate(f.EarlyDiscard, MethodInfo(f.Method).NeedsPsiTable,
    MethodInfo(f.Method).NeedsPreIntegrationTable);
}

int vtkPsiVolumeMapper::GetMeshVersion() const
{
  return this->Impl->Mesh.GetVersion();
}

void vtkPsiVolumeMapper::SetRecordDrawOrder(bool on)
{
  this->Impl->Order.SetRecordDrawn(on);
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
  os << indent << "IntegrationMethod: " << GetIntegrationMethodName(this->IntegrationMethod)
     << "\n";
  os << indent << "TransferFunctionSamples: " << this->TransferFunctionSamples << "\n";
  os << indent << "IsosurfaceMethod: " << this->IsosurfaceMethod
     << ", IsosurfaceShading: " << this->IsosurfaceShading << "\n";
  os << indent << "NumberOfTetrahedra: " << this->Stats.NumberOfTetrahedra << "\n";
  os << indent << "NumberOfSkippedCells: " << this->Stats.NumberOfSkippedCells << "\n";
}
