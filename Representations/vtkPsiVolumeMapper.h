/**
 * @class   vtkPsiVolumeMapper
 * @brief   Projected tetrahedra in a geometry shader (Maximo et al. 2010) with selectable ray
 *          integration (Moreland & Angel 2004 and the methods of Moreland's dissertation).
 *
 * The mapper conducts one frame through parts that each own one job and its GPU resources
 * (docs/architecture.md follows a frame through them):
 *  - PsiMeshBuffers: the tetrahedra gathered from the input (psi::GatherTetMesh) and uploaded
 *    once: points as a texture buffer, one uvec4 attribute of point ids per tetrahedron;
 *  - PsiVisibilityOrder: back-to-front order (centroid or MPVONC, psi::TetSort) as an index
 *    buffer of GL_POINTS, re-sorted when the view changes;
 *  - PlanFrame (PsiFramePlan.h): what the scene calls for, from the settings and the scene's
 *    facts, with no GL call: the features and the tables they read;
 *  - PsiTransferTextures, PsiAdaptiveNodes: transfer function, opacity prefix, Psi and
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

#include "PsiVolumeRepresentationsModule.h"
#include "vtkUnstructuredGridVolumeMapper.h"

#include "PsiFrameStats.h"
#include "PsiIsosurfaceList.h"

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
struct PsiFrameSettings;
struct PsiSceneFacts;
struct PsiTableSources;
namespace psi
{
struct ShaderFeatures;
}

class PSIVOLUMEREPRESENTATIONS_EXPORT vtkPsiVolumeMapper : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkPsiVolumeMapper* New();
  vtkTypeMacro(vtkPsiVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Ray integration within each cell: a psi::Method value, i.e. a row of
  /// psi::IntegrationMethodTable() (PsiIntegrationMethods.h), which documents each; clamped to
  /// the table's rows. Default psi::Method::PartialPreIntegration.
  virtual void SetIntegrationMethod(int method);
  vtkGetMacro(IntegrationMethod, int);
  static const char* GetIntegrationMethodName(int method);

  /// In perspective, reconstruct each fragment's segment exactly from the two face planes of its
  /// fan triangle (default on) instead of HAPT's screen-linear interpolation of front scalar,
  /// back scalar and thickness, which is exact only in parallel projection (where it is used).
  vtkSetMacro(ExactPerspectiveSegments, bool);
  vtkGetMacro(ExactPerspectiveSegments, bool);
  vtkBooleanMacro(ExactPerspectiveSegments, bool);

  /// Visibility order: MPVONC (Williams 1992, default), which orders across shared faces exactly
  /// (for convex meshes) using the mesh connectivity, or the centroid sort, faster but wrong
  /// across some shared faces: on the Kuhn cells of structured grids (long and thin) seen head-on
  /// it draws visible lines (TestPsiVolumeRender: max error 0.054 vs 0.005 with MPVONC).
  enum SortMethods
  {
    CENTROID = 0,
    MPVONC = 1
  };
  vtkSetClampMacro(SortMethod, int, CENTROID, MPVONC);
  vtkGetMacro(SortMethod, int);

  /// HAPT §3.5: drop tetrahedra whose scalar range sees zero opacity only, in the geometry shader
  /// (default on; compiled in only when the opacity function has zero regions). With
  /// marching-tetrahedra isosurfaces only the transparent pieces of a cell are dropped, its
  /// surfaces are still drawn; per-fragment isosurfaces switch it off.
  vtkSetMacro(EarlyDiscard, bool);
  vtkGetMacro(EarlyDiscard, bool);
  vtkBooleanMacro(EarlyDiscard, bool);
  /// Whether the last frame used early discard.
  vtkGetMacro(LastUsedEarlyDiscard, bool);

  /// Which stage projects the tetrahedra (both run the same classification and emission code,
  /// Shaders/PsiVolumeGS.glsl with its features):
  ///  - PROJECTOR_GEOMETRY_SHADER: a geometry shader per tetrahedron (Maximo et al. 2010 §3.2);
  ///  - PROJECTOR_COMPUTE_SHADER: a compute pass writes each chunk's triangles in visibility
  ///    order, drawn by a pass-through vertex shader (needs OpenGL 4.3; else the geometry
  ///    shader is used, with a warning). Compute shaders run on all of a CPU driver's threads.
  ///  - PROJECTOR_AUTO (default): the environment's PSI_PROJECTOR ("geometry" or "compute", a
  ///    site's choice) when set, else the geometry shader, measured the faster of the two with
  ///    Mesa's llvmpipe (docs/decisions.md, "Projectors"; the compute projector needs far less memory
  ///    there).
  enum Projectors
  {
    PROJECTOR_GEOMETRY_SHADER = 0,
    PROJECTOR_COMPUTE_SHADER = 1,
    PROJECTOR_AUTO = 2
  };
  vtkSetClampMacro(Projector, int, PROJECTOR_GEOMETRY_SHADER, PROJECTOR_AUTO);
  vtkGetMacro(Projector, int);
  /// The projector the last frame used.
  vtkGetMacro(LastUsedProjector, int);

  /// How each tetrahedron's projection is drawn:
  ///  - DECOMPOSITION_SILHOUETTE: its silhouette, the convex hull of its projected vertices (1 or
  ///    2 triangles), each fragment intersecting its ray with the four face planes; exact in
  ///    both projections (PsiRaySegments*.glsl). Half the triangles of the fan, and on Mesa's
  ///    llvmpipe about a fifth less time per frame (docs/decisions.md, "Silhouettes").
  ///  - DECOMPOSITION_FAN: Shirley and Tuchman's 1-4 triangles around the thick vertex, as HAPT
  ///    draws them (Maximo et al. 2010 §3.2), with ExactPerspectiveSegments in perspective.
  ///  - DECOMPOSITION_AUTO (default): the environment's PSI_DECOMPOSITION ("silhouette" or
  ///    "fan") when set, else the silhouette.
  enum Decompositions
  {
    DECOMPOSITION_SILHOUETTE = 0,
    DECOMPOSITION_FAN = 1,
    DECOMPOSITION_AUTO = 2
  };
  vtkSetClampMacro(Decomposition, int, DECOMPOSITION_SILHOUETTE, DECOMPOSITION_AUTO);
  vtkGetMacro(Decomposition, int);

  /// Number of samples of the transfer function table (default 1024).
  vtkSetClampMacro(TransferFunctionSamples, int, 2, 1 << 16);
  vtkGetMacro(TransferFunctionSamples, int);

  ///@{
  /// Isosurfaces drawn inside the volume, in exact visibility order with the volume inside every
  /// cell (see IsosurfaceMethod). Values may come in any order: when set they are sorted, and
  /// duplicates and non-finite values dropped (psi::IsosurfaceList); at most
  /// psi::IsosurfaceList::MaxCount (32) are drawn, with a warning. With none, the program is the
  /// plain volume's: no cost at all.
  void SetNumberOfIsosurfaces(int n);
  int GetNumberOfIsosurfaces() const { return static_cast<int>(this->IsosurfaceValues.size()); }
  void SetIsosurfaceValue(int i, double value);
  double GetIsosurfaceValue(int i) const;
  void SetIsosurfaceValues(const std::vector<double>& values);
  /// Opacity of every isosurface, 0..1 (default 1: opaque, hides what is behind it).
  void SetIsosurfaceOpacity(double opacity);
  vtkGetMacro(IsosurfaceOpacity, double);
  /// Each isosurface's own opacity, in the order of the isovalues as given: entry i applies to
  /// isovalue i; isovalues without an entry use IsosurfaceOpacity. Values are clamped to 0..1.
  void SetNumberOfIsosurfaceOpacities(int n);
  void SetIsosurfaceOpacityValue(int i, double opacity);
  void SetIsosurfaceOpacities(const std::vector<double>& opacities);
  const std::vector<double>& GetIsosurfaceOpacities() const { return this->IsosurfaceOpacities; }
  /// Solid color of the isosurfaces, used when IsosurfaceUseColorMap is off.
  vtkSetVector3Macro(IsosurfaceColor, double);
  vtkGetVector3Macro(IsosurfaceColor, double);
  /// Color each isosurface through the color map at its value (default on).
  vtkSetMacro(IsosurfaceUseColorMap, bool);
  vtkGetMacro(IsosurfaceUseColorMap, bool);
  vtkBooleanMacro(IsosurfaceUseColorMap, bool);
  /// Shade the isosurfaces with the renderer's lights (default on; off: unlit color).
  vtkSetMacro(IsosurfaceLighting, bool);
  vtkGetMacro(IsosurfaceLighting, bool);
  vtkBooleanMacro(IsosurfaceLighting, bool);
  /// How isosurfaces are drawn (HAPT §3.4 names both):
  ///  - ISO_MARCHING_TETRAHEDRA: the geometry shader extracts each crossing cell's
  ///    surface as one or two triangles and draws them in visibility order with the volume: the
  ///    cell's volume once per scalar interval between its crossings, farthest first, with the
  ///    surfaces in between (Roettger et al. §10). Cells with no crossing draw as without
  ///    isosurfaces. The geometry shader's output grows with the number of isovalues, within the
  ///    GL limit (GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS); beyond it the per-fragment method is
  ///    used (see GetLastUsedIsosurfaceMethod).
  ///  - ISO_PER_FRAGMENT: every fragment finds the crossings along its own ray segment and
  ///    composites the surfaces there (no extra geometry; every fragment pays the search).
  ///  - ISO_AUTO (default): marching tetrahedra when early discard applies (the opacity function
  ///    has zero regions, e.g. plain contours: only the surfaces and the visible pieces are
  ///    drawn), per fragment otherwise. Both give the same image (docs/benchmarks.md has the costs).
  enum IsosurfaceMethods
  {
    ISO_MARCHING_TETRAHEDRA = 0,
    ISO_PER_FRAGMENT = 1,
    ISO_AUTO = 2
  };
  vtkSetClampMacro(IsosurfaceMethod, int, ISO_MARCHING_TETRAHEDRA, ISO_AUTO);
  vtkGetMacro(IsosurfaceMethod, int);
  /// Method the last frame used for its isosurfaces, -1 when it drew none.
  vtkGetMacro(LastUsedIsosurfaceMethod, int);
  /// Flat shading uses each cell's own gradient as the normal (HAPT §3.4); smooth (default)
  /// interpolates the smoothed point gradients (volume-weighted averages of the cells' gradients).
  enum IsosurfaceShadings
  {
    ISO_FLAT = 0,
    ISO_SMOOTH = 1
  };
  vtkSetClampMacro(IsosurfaceShading, int, ISO_FLAT, ISO_SMOOTH);
  vtkGetMacro(IsosurfaceShading, int);
  ///@}

  /// Adaptive transfer-function sampling (Moreland §4.3): split each ray segment at the
  /// transfer function's control points inside its scalar range, so that color and attenuation
  /// are linear on each piece. AUTO uses it only when the transfer function has interior control
  /// points where it bends (nonlinear over the data range).
  enum AdaptiveSamplingModes
  {
    ADAPTIVE_OFF = 0,
    ADAPTIVE_ON = 1,
    ADAPTIVE_AUTO = 2
  };
  vtkSetClampMacro(AdaptiveSampling, int, ADAPTIVE_OFF, ADAPTIVE_AUTO);
  vtkGetMacro(AdaptiveSampling, int);

  /// Largest number of transfer-function nodes used for adaptive sampling (more are thinned).
  static constexpr int MaxAdaptiveNodes = 64;
  /// Adaptive sampling adds nodes where a color map bends farther than this from linear
  /// interpolation between its nodes (psi::SampleTransferFunctionNodes).
  static constexpr double AdaptiveNodeTolerance = 1.0 / 512;
  /// 'Auto' samples adaptively when the sampled table misses the transfer function by more
  /// than this at a node (psi::TableDeviation): a feature narrower than the table resolves.
  static constexpr double AdaptiveAutoDeviation = 1.0 / 255;
  /// Largest number of isosurfaces (more are ignored with a warning).
  static constexpr int MaxIsosurfaces = psi::IsosurfaceList::MaxCount;

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

  ///@{
  /// What the last Render did: tetrahedra drawn, cells skipped (non-tetrahedra, non-finite
  /// scalars), CPU seconds spent sorting and in the whole call (GL work is asynchronous: call
  /// vtkRenderWindow::WaitForCompletion() before reading a wall-clock frame time).
  const psi::FrameStats& GetFrameStats() const { return this->Stats; }
  vtkIdType GetNumberOfTetrahedra() const { return this->Stats.NumberOfTetrahedra; }
  vtkIdType GetNumberOfSkippedCells() const { return this->Stats.NumberOfSkippedCells; }
  double GetLastSortSeconds() const { return this->Stats.LastSortSeconds; }
  /// Seconds spent rebuilding the full pre-integration table (last rebuild).
  double GetLastPreIntegrationSeconds() const { return this->Stats.LastPreIntegrationSeconds; }
  /// Cycles MPVONC had to break in the last sort.
  vtkIdType GetLastSortCycles() const { return this->Stats.LastSortCycles; }
  double GetLastRenderSeconds() const { return this->Stats.LastRenderSeconds; }
  /// Testing aid, off by default: record the tetrahedra in the order each frame streams them to
  /// the GPU (GetLastDrawOrder; 4 bytes per tetrahedron).
  void SetRecordDrawOrder(bool on);
  /// The tetrahedra in the order the last frame drew them (farthest first; ids of the gathered
  /// mesh, which are the input's cell ids when every cell is a drawable tetrahedron), when
  /// recorded (SetRecordDrawOrder); empty otherwise.
  const std::vector<uint32_t>& GetLastDrawOrder() const;
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
  const std::string& GetLastFeatureDefines() const { return this->LastFeatureDefines; }
  /// Number of distinct programs this mapper has compiled (or fetched from the shader cache).
  vtkGetMacro(NumberOfProgramBuilds, int);
  ///@}

protected:
  vtkPsiVolumeMapper();
  ~vtkPsiVolumeMapper() override;

  int IntegrationMethod = 1; // psi::Method::PartialPreIntegration, the XML default
  int TransferFunctionSamples = 1024;
  int SortMethod = MPVONC;
  int Projector = PROJECTOR_AUTO;
  int Decomposition = DECOMPOSITION_AUTO;
  int LastUsedProjector = PROJECTOR_GEOMETRY_SHADER;
  bool ExactPerspectiveSegments = true;
  bool EarlyDiscard = true;
  bool LastUsedEarlyDiscard = false;
  bool LastUsedNearPlaneClipping = false;
  bool LastUsedOpaqueClipping = false;
  std::vector<double> IsosurfaceValues;
  double IsosurfaceOpacity = 1.0;
  std::vector<double> IsosurfaceOpacities;
  psi::IsosurfaceList Isosurfaces; ///< normalized from the three above when they are set
  psi::FrameStats Stats;
  double IsosurfaceColor[3] = { 1.0, 1.0, 1.0 };
  bool IsosurfaceUseColorMap = true;
  bool IsosurfaceLighting = true;
  int IsosurfaceMethod = ISO_AUTO;
  int IsosurfaceShading = ISO_SMOOTH;
  int LastUsedIsosurfaceMethod = -1;
  int AdaptiveSampling = ADAPTIVE_AUTO;
  bool LastUsedAdaptiveSampling = false;
  int LastNumberOfAdaptiveNodes = 0;
  std::string LastFeatureDefines;
  int NumberOfProgramBuilds = 0;

private:
  vtkPsiVolumeMapper(const vtkPsiVolumeMapper&) = delete;
  void operator=(const vtkPsiVolumeMapper&) = delete;

  void SetIsosurfaceVector(std::vector<double>& member, std::vector<double> v);
  void UpdateIsosurfaceList();
  bool UpdateMesh(
    vtkOpenGLRenderWindow* renWin, vtkVolume* vol, vtkUnstructuredGridBase* input);
  bool UpdateVisibilityOrder(vtkUnstructuredGridBase* input, const PsiFrameCamera& cam);
  // the frame plan (vtkPsiVolumeMapperFramePlan.cxx)
  PsiTableSources UpdateTransferFunction(
    vtkOpenGLRenderWindow* renWin, vtkVolume* vol, const PsiFrameSettings& settings);
  PsiFrameSettings FrameSettings() const;
  PsiSceneFacts SceneFacts(vtkRenderer* ren, vtkVolume* vol, const PsiFrameCamera& cam,
    const PsiFrameSettings& settings);
  void NotePlan(const PsiFramePlan& plan);
  std::vector<PsiGpuTable*> TablesOf(const PsiFramePlan& plan);
  void UpdateTables(vtkOpenGLRenderWindow* renWin, const PsiFramePlan& plan,
    const std::vector<PsiGpuTable*>& tables, const PsiTableSources& sources);
  // the draw (vtkPsiVolumeMapper.cxx)
  vtkShaderProgram* ReadyProjection(
    vtkOpenGLRenderWindow* renWin, const psi::ShaderFeatures& features, bool compute);
  void DrawVolume(vtkOpenGLRenderWindow* renWin, vtkRenderer* ren, vtkVolume* vol,
    const PsiFrameCamera& cam, const PsiFramePlan& plan, const std::vector<PsiGpuTable*>& tables);
  void SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkVolume* vol,
    const PsiFrameCamera& cam, const psi::ShaderFeatures& features,
    const std::vector<PsiGpuTable*>& tables);

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
