/**
 * @class   vtkPsiVolumeMapper
 * @brief   Projected tetrahedra in a geometry shader (Maximo et al. 2010) with selectable ray
 *          integration (Moreland & Angel 2004 and the methods of Moreland's dissertation).
 *
 * The mapper conducts one frame through parts that each own one job and its GPU resources
 * (docs/architecture.md follows a frame through them):
 *  - PsiMeshBuffers: the tetrahedra gathered from the input (psi::GatherTetMesh) and uploaded
 *    once: the points as a texture buffer;
 *  - PsiVisibilityOrder: back-to-front order (centroid or MPVONC, psi::VisibilitySort), sorted on a
 *    worker thread when the view changes, each tetrahedron's four point ids streamed to the GPU
 *    as one GL_POINTS vertex, chunk by chunk as the sort emits them;
 *  - PlanFrame (PsiFramePlan.h): what the scene calls for, from the settings (psi::Settings,
 *    Core/PsiSettings.h) and the scene's facts, with no GL call: the features and the tables
 *    they read;
 *  - PsiTableTextures, PsiAdaptiveNodes: transfer function, opacity prefix, Psi and
 *    pre-integration tables, adaptive nodes, each a PsiGpuTable;
 *  - psi::ComposeShaders: the program for the plan's features;
 *  - PsiRenderTarget: scene depth copies, the float target, the composite over the scene.
 * A geometry shader classifies each projection with the PTINT ternary truth table (Marroquim et
 * al. 2008) and emits 1-4 triangles; a fragment shader integrates each ray segment.
 *
 * Cell scalars are supported by giving each tetrahedron its own four points (constant scalar).
 * Cells that are not tetrahedra, and tetrahedra with a NaN/Inf scalar, are skipped and counted
 * (see GetNumberOfSkippedCells) with a warning naming the reason.
 */
#ifndef vtkPsiVolumeMapper_h
#define vtkPsiVolumeMapper_h

#include "PsiVolumeRenderingModule.h"
#include "vtkUnstructuredGridVolumeMapper.h"

#include "PsiFrameStats.h"
#include "PsiIsosurfaceList.h"
#include "PsiSettingList.h" // PSI_RENDER_SETTINGS: the setters below
#include "PsiSettings.h"
#include "vtkLogger.h" // for vtkLogger::Verbosity

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkVolume;
class vtkWindow;
class PsiGpuTable;
struct PsiFrameCamera;
struct PsiFramePlan;
struct PsiSceneFacts;
struct PsiTableSources;
namespace psi
{
struct ShaderFeatures;
class Stopwatch;
}

class PSIVOLUMERENDERING_EXPORT vtkPsiVolumeMapper : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkPsiVolumeMapper* New();
  vtkTypeMacro(vtkPsiVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The user's settings (Core/PsiSettings.h documents each, its values and its default): set
  /// one by one below, clamped there to their range with one warning, or all at once.
  const psi::Settings& GetSettings() const { return this->Settings; }
  void SetSettings(const psi::Settings& settings);
  ///@}

  ///@{
  /// One Set/Get per setting of PSI_RENDER_SETTINGS (Core/PsiSettingList.h documents each, its
  /// values and its default): an enumeration by its number (the XML's, for ParaView and Python)
  /// or, from C++, by its typed enumerator; clamped to its range with one warning
  /// (psi::SetClamped); a boolean also with On/Off.
#ifdef __VTK_WRAP__
#define PSI_MAPPER_TYPED_SETTER(Name, Type)
#else
#define PSI_MAPPER_TYPED_SETTER(Name, Type)                                                        \
  void Set##Name(psi::Type value)                                                                  \
  {                                                                                                \
    this->Set##Name(static_cast<int>(value));                                                      \
  }
#endif
#define PSI_MAPPER_ENUM(Name, Type, Default, Last)                                                 \
  void Set##Name(int value)                                                                        \
  {                                                                                                \
    this->SetRanged(psi::Setting::Name, value);                                                    \
  }                                                                                                \
  PSI_MAPPER_TYPED_SETTER(Name, Type)                                                              \
  int Get##Name() const                                                                            \
  {                                                                                                \
    return static_cast<int>(this->Settings.Name);                                                  \
  }
#define PSI_MAPPER_NUMBER(Name, Type, Default, Min, Max, Where)                                    \
  void Set##Name(Type value)                                                                       \
  {                                                                                                \
    this->SetRanged(psi::Setting::Name, value);                                                    \
  }                                                                                                \
  Type Get##Name() const                                                                           \
  {                                                                                                \
    return this->Settings.Name;                                                                    \
  }
#define PSI_MAPPER_BOOL(Name, Default, Where)                                                      \
  void Set##Name(bool on)                                                                          \
  {                                                                                                \
    this->SetRanged(psi::Setting::Name, on);                                                       \
  }                                                                                                \
  bool Get##Name() const                                                                           \
  {                                                                                                \
    return this->Settings.Name;                                                                    \
  }                                                                                                \
  vtkBooleanMacro(Name, bool);
  PSI_RENDER_SETTINGS(PSI_MAPPER_ENUM, PSI_MAPPER_NUMBER, PSI_MAPPER_BOOL)
#undef PSI_MAPPER_ENUM
#undef PSI_MAPPER_NUMBER
#undef PSI_MAPPER_BOOL
#undef PSI_MAPPER_TYPED_SETTER
  /// The name of integration method `method` (psi::IntegrationMethodTable()).
  static const char* GetIntegrationMethodName(int method);
  /// The projector the last frame used (psi::Projectors::GeometryShader or ComputeShader).
  vtkGetMacro(LastUsedProjector, int);
  /// Whether the last frame used early discard.
  vtkGetMacro(LastUsedEarlyDiscard, bool);
  /// Whether the last frame composited front to back with early ray termination.
  vtkGetMacro(LastUsedEarlyRayTermination, bool);
  /// How the last frame drew each projection (psi::Decompositions::Silhouette or Fan).
  vtkGetMacro(LastUsedDecomposition, int);
  /// The opacity masks the last frame drew at first, front to back (0: back to front).
  vtkGetMacro(LastUsedMasksPerFrame, int);
  /// The last frame's way in words, and how it was chosen: "back to front, geometry shader,
  /// silhouettes (chosen by measurement of 4 ways)"; "(measuring (way 2))" while the first
  /// frames time the ways open under 'Auto'; "(as set)" when none is (psi::MeasuredChoice).
  const std::string& GetLastDrawWay() const
  {
    return this->Stats.DrawWay;
  }
  ///@}

  ///@{
  /// Isosurfaces drawn inside the volume, in exact visibility order with the volume inside every
  /// cell. Values may come in any order: the list drawn is sorted, and duplicates and non-finite
  /// values dropped (psi::IsosurfaceList); at most psi::IsosurfaceList::MaxCount (32) are drawn,
  /// with a warning. With none, the program is the plain volume's: no cost at all.
  void SetNumberOfIsosurfaces(int n);
  int GetNumberOfIsosurfaces() const
  {
    return static_cast<int>(this->Settings.IsosurfaceValues.size());
  }
  void SetIsosurfaceValue(int i, double value);
  double GetIsosurfaceValue(int i) const;
  void SetIsosurfaceValues(const std::vector<double>& values);
  /// Each isosurface's own opacity, in the order of the isovalues as given: entry i applies to
  /// isovalue i; isovalues without an entry use IsosurfaceOpacity. Values are clamped to 0..1.
  void SetNumberOfIsosurfaceOpacities(int n);
  void SetIsosurfaceOpacityValue(int i, double opacity);
  void SetIsosurfaceOpacities(const std::vector<double>& opacities);
  const std::vector<double>& GetIsosurfaceOpacities() const
  {
    return this->Settings.IsosurfaceOpacities;
  }
  /// Solid color of the isosurfaces, used when IsosurfaceUseColorMap is off.
  void SetIsosurfaceColor(double r, double g, double b);
  const double* GetIsosurfaceColor() const
  {
    return this->Settings.IsosurfaceColor;
  }
  /// Method the last frame used for its isosurfaces, -1 when it drew none.
  vtkGetMacro(LastUsedIsosurfaceMethod, int);
  ///@}

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;
  /// The bounds of the points the input's cells use (psi::CellPointBounds), not of its whole
  /// point list: a point no cell uses does not widen the volume (the camera's clipping range, a
  /// ray's longest path). The dataset's own bounds when every point is used.
  double* GetBounds() override;
  using Superclass::GetBounds;

  ///@{
  /// What the last Render did: tetrahedra drawn, cells skipped (non-tetrahedra, non-finite
  /// scalars), CPU seconds spent sorting and in the whole call (GL work is asynchronous: call
  /// vtkRenderWindow::WaitForCompletion() before reading a wall-clock frame time).
  const psi::FrameStats& GetFrameStats() const
  {
    return this->Stats;
  }
  vtkIdType GetNumberOfTetrahedra() const
  {
    return this->Stats.NumberOfTetrahedra;
  }
  vtkIdType GetNumberOfSkippedCells() const
  {
    return this->Stats.NumberOfSkippedCells;
  }
  double GetLastSortSeconds() const
  {
    return this->Stats.LastSortSeconds;
  }
  /// Seconds spent rebuilding the full pre-integration table (last rebuild).
  double GetLastPreIntegrationSeconds() const
  {
    return this->Stats.LastPreIntegrationSeconds;
  }
  /// Cycles MPVONC had to break in the last sort.
  vtkIdType GetLastSortCycles() const
  {
    return this->Stats.LastSortCycles;
  }
  /// Seconds of the last frame's Render calls (under dual depth peeling, one call per stage).
  double GetLastRenderSeconds() const
  {
    return this->Stats.LastRenderSeconds;
  }
  /// The Render calls that made the last frame (1, or its depth-peeling stages).
  int GetLastFrameCalls() const
  {
    return this->Frame.Calls;
  }
  /// Several volumes intermixed: the volumes drawn in one pass with this one (0: drawn alone),
  /// and that draw's tetrahedra (the times above are that draw's too).
  vtkIdType GetNumberOfIntermixedVolumes() const
  {
    return this->Stats.IntermixedVolumes;
  }
  vtkIdType GetNumberOfIntermixedTetrahedra() const
  {
    return this->Stats.IntermixedTetrahedra;
  }
  /// Seconds of the last still (not interactive, psi::IsInteractiveRender) frame: what 'Auto'
  /// interaction weighs against the budget (psi::UsesVolumeLOD).
  vtkGetMacro(LastStillSeconds, double);
  /// Testing aid, off by default: record the tetrahedra in the order each frame streams them to
  /// the GPU (GetLastDrawOrder; 4 bytes per tetrahedron).
  void SetRecordDrawOrder(bool on);
  /// The tetrahedra in the order the last frame drew them (farthest first, or nearest first with
  /// early ray termination, GetLastUsedEarlyRayTermination; ids of the gathered
  /// mesh, which are the input's cell ids when every cell is a drawable tetrahedron), when
  /// recorded (SetRecordDrawOrder); empty otherwise.
  const std::vector<uint32_t>& GetLastDrawOrder() const;
  /// Testing aid, off by default: count the volume's samples that pass the depth test each frame
  /// (GL_SAMPLES_PASSED over the volume's draws; each count waits for the draws): fragments
  /// behind opaque pixels fail it before they are shaded when the frame terminates rays early.
  void SetCountSamplesPassed(bool on);
  /// The last frame's count (SetCountSamplesPassed); 0 when not counted.
  vtkIdType GetLastSamplesPassed() const;
  /// Testing aid: the driver's buffer limits lowered to these (texels of a texture buffer, bytes
  /// of a shader storage block; 0 keeps the driver's), so that a small mesh crosses them
  /// (PsiDriverLimits.h). Takes effect when the mesh is next gathered and on the next draw.
  void SetDriverLimitsForTesting(long long maxTextureBufferTexels, long long maxStorageBlockBytes);
  /// Bumped when the mesh is gathered again (points or cells changed), not for new scalars.
  int GetMeshVersion() const;
  /// Zeroes the read-outs above (no frame drawn, e.g. empty input).
  void ResetStatistics();
  /// Whether the last frame needed the near-plane path (camera inside or close to the mesh).
  vtkGetMacro(LastUsedNearPlaneClipping, bool);
  /// Whether the last frame clipped segments at opaque geometry overlapping the volume.
  vtkGetMacro(LastUsedOpaqueClipping, bool);
  /// Whether the last frame split segments at transfer-function nodes, and at how many nodes.
  vtkGetMacro(LastUsedAdaptiveSampling, bool);
  vtkGetMacro(LastNumberOfAdaptiveNodes, int);
  /// The feature defines the last frame's program was composed from (one "#define" a line).
  const std::string& GetLastFeatureDefines() const
  {
    return this->LastFeatureDefines;
  }
  ///@}

  /// The verbosity at which each frame logs its stages' scopes and times (vtkLogger; TRACE by
  /// default). ParaView's representation sets its rendering verbosity
  /// (PARAVIEW_LOG_RENDERING_VERBOSITY, or --verbosity).
  vtkSetMacro(LogVerbosity, vtkLogger::Verbosity);
  vtkGetMacro(LogVerbosity, vtkLogger::Verbosity);

  /// Whether the volume's holder draws something else in its place in the coming frames
  /// (ParaView's representation: a level of detail while the camera moves). The renderer's
  /// intermixed volumes then leave this one out (PsiIntermixedFrames::Members): it is not drawn
  /// twice. Off by default.
  vtkSetMacro(DrawnByStandIn, bool);
  vtkGetMacro(DrawnByStandIn, bool);

protected:
  vtkPsiVolumeMapper();
  ~vtkPsiVolumeMapper() override;

  psi::Settings Settings;
  vtkLogger::Verbosity LogVerbosity = vtkLogger::VERBOSITY_TRACE;
  int LastUsedProjector = 0; ///< psi::Projectors::GeometryShader
  bool LastUsedEarlyDiscard = false;
  bool LastUsedEarlyRayTermination = false;
  int LastUsedDecomposition = 0; ///< psi::Decompositions::Silhouette
  int LastUsedMasksPerFrame = 0;
  bool LastUsedNearPlaneClipping = false;
  bool LastUsedOpaqueClipping = false;
  psi::IsosurfaceList Isosurfaces; ///< Settings' isovalues normalized, when they are set
  psi::FrameStats Stats;
  int LastUsedIsosurfaceMethod = -1;
  bool LastUsedAdaptiveSampling = false;
  int LastNumberOfAdaptiveNodes = 0;
  std::string LastFeatureDefines;
  double LastStillSeconds = 0;
  bool DrawnByStandIn = false;
  psi::FrameClock Frame; ///< the current frame's calls (one per depth-peeling stage)

private:
  vtkPsiVolumeMapper(const vtkPsiVolumeMapper&) = delete;
  void operator=(const vtkPsiVolumeMapper&) = delete;

#ifndef __VTK_WRAP__
  void SetRanged(psi::Setting id, double value);
#endif
  void SetIsosurfaceVector(std::vector<double>& member, std::vector<double> v);
  void UpdateIsosurfaceList();
  // several volumes intermixed (vtkPsiVolumeMapperIntermixed.cxx)
  bool RenderIntermixed(vtkRenderer* ren, vtkVolume* vol);
  void UpdateGivenMesh();
  void CountOwnCells();
  bool UpdateMesh(vtkVolume* vol, vtkUnstructuredGridBase* input);
  bool UploadMesh(vtkOpenGLRenderWindow* renWin);
  bool UpdateVisibilityOrder(
    vtkUnstructuredGridBase* input, const PsiFrameCamera& cam, bool frontToBack);
  // the frame plan (vtkPsiVolumeMapperFramePlan.cxx)
  PsiTableSources UpdateTransferFunction(vtkOpenGLRenderWindow* renWin, vtkVolume* vol);
  PsiSceneFacts SceneFacts(vtkRenderer* ren, vtkVolume* vol, const PsiFrameCamera& cam);
  PsiFramePlan ChooseWay(const PsiFramePlan& plan, vtkRenderer* ren, const PsiFrameCamera& cam);
  void TimeWay(const psi::Stopwatch& draw, double programSeconds);
  void NotePlan(const PsiFramePlan& plan);
  std::vector<PsiGpuTable*> TablesOf(const PsiFramePlan& plan);
  void UpdateTables(vtkOpenGLRenderWindow* renWin, const PsiFramePlan& plan,
    const std::vector<PsiGpuTable*>& tables, const PsiTableSources& sources);
  // the draw (vtkPsiVolumeMapper.cxx)
  vtkShaderProgram* ReadyProjection(
    vtkOpenGLRenderWindow* renWin, const psi::ShaderFeatures& features, bool compute);
  double DrawVolume(vtkOpenGLRenderWindow* renWin, vtkRenderer* ren, vtkVolume* vol,
    const PsiFrameCamera& cam, const PsiFramePlan& plan, const std::vector<PsiGpuTable*>& tables);
  void DrawImage(vtkOpenGLRenderWindow* renWin, vtkVolume* vol, const PsiFramePlan& plan,
    vtkShaderProgram* draw, bool compute, int image, std::string& error);
  void SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkVolume* vol,
    const PsiFrameCamera& cam, const PsiFramePlan& plan, const std::vector<PsiGpuTable*>& tables);

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
