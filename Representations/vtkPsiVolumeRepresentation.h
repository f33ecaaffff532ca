/**
 * @class   vtkPsiVolumeRepresentation
 * @brief   ParaView's unstructured-grid volume representation, drawn by vtkPsiVolumeMapper.
 *
 * Everything a ParaView user knows from 'Volume' is inherited from
 * vtkUnstructuredGridVolumeRepresentation: the color map and opacity function, the
 * ScalarOpacityUnitDistance, ordered compositing in parallel, and state files. This subclass
 * registers its own mapper as the only volume mapper and forwards its options. Non-tetrahedral
 * input (hexahedra, voxels, wedges, pyramids, prisms, polyhedra, structured data) goes through
 * the project's conforming tetrahedralization (vtkPsiConformingTetrahedralize: neighbouring
 * cells split their shared faces alike, no zero-volume tetrahedra, face neighbours for MPVONC),
 * once per input change, instead of VTK's generic triangulator.
 */
#ifndef vtkPsiVolumeRepresentation_h
#define vtkPsiVolumeRepresentation_h

#include "PsiFrameStats.h"
#include "PsiSettingList.h" // PSI_RENDER_SETTINGS, PSI_INTERACTION_SETTINGS: the setters below
#include "PsiSettings.h"
#include "PsiVolumeRepresentationsModule.h"
#include "vtkNew.h"
#include "vtkUnstructuredGridVolumeRepresentation.h"

#include <memory>

class vtkPsiConformingTetrahedralize;
class vtkPsiVolumeMapper;
class PsiLevelOfDetail;
class vtkPVRenderView;

class PSIVOLUMEREPRESENTATIONS_EXPORT vtkPsiVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  static vtkPsiVolumeRepresentation* New();
  vtkTypeMacro(vtkPsiVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The mapper is fixed to vtkPsiVolumeMapper; the inherited 'SelectMapper' is ignored.
  void SetActiveVolumeMapper(const char*) override;

  using Superclass::GetInternalOutputPort;
  /// Port 0 of non-tetrahedral input is the conforming tetrahedralization's output (see the
  /// class documentation).
  vtkAlgorithmOutput* GetInternalOutputPort(int port, int conn) override;

  ///@{
  /// One setter per setting of PSI_RENDER_SETTINGS and PSI_INTERACTION_SETTINGS
  /// (Core/PsiSettingList.h documents each): the XML's numbers, clamped with one warning. The
  /// first go to the mapper; the second, what an interactive render (the camera moving) draws,
  /// stay here (psi::InteractionSettings): 'Auto' draws the volume level of detail
  /// (PsiLevelOfDetail: this process's piece resampled on a coarse lattice, drawn by VTK's GPU
  /// ray caster with the same color map, opacity function and unit distance) when the last still
  /// frame took longer than InteractiveBudget seconds. Still renders and screenshots are always
  /// the full frame.
#define PSI_REPRESENTATION_ENUM(Name, Type, Default, Last) void Set##Name(int value);
#define PSI_REPRESENTATION_NUMBER(Name, Type, Default, Min, Max, Where) void Set##Name(Type value);
#define PSI_REPRESENTATION_BOOL(Name, Default, Where) void Set##Name(int on);
  PSI_RENDER_SETTINGS(PSI_REPRESENTATION_ENUM, PSI_REPRESENTATION_NUMBER, PSI_REPRESENTATION_BOOL)
  PSI_INTERACTION_SETTINGS(
    PSI_REPRESENTATION_ENUM, PSI_REPRESENTATION_NUMBER, PSI_REPRESENTATION_BOOL)
#undef PSI_REPRESENTATION_ENUM
#undef PSI_REPRESENTATION_NUMBER
#undef PSI_REPRESENTATION_BOOL
  ///@}

  ///@{
  /// Isosurfaces: see vtkPsiVolumeMapper.
  void SetNumberOfIsosurfaces(int n);
  void SetIsosurfaceValue(int i, double value);
  void SetNumberOfIsosurfaceOpacities(int n);
  void SetIsosurfaceOpacityValue(int i, double opacity);
  void SetIsosurfaceColor(double r, double g, double b);
  int GetLastUsedIsosurfaceMethod();
  /// Nodes adaptive sampling used in the last frame (0: it was not used).
  int GetLastNumberOfAdaptiveNodes();
  ///@}

  ///@{
  /// What drew the last interactive frame: psi::InteractiveImages (-1 no interactive frame yet).
  vtkGetMacro(LastInteractiveImage, int);
  /// Seconds the last interactive frame's volume took to draw on this process.
  double GetLastInteractiveSeconds();
  /// Seconds the last build of the volume level of detail took (0: never built).
  double GetLODBuildSeconds();
  ///@}

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  ///@{
  /// Read-outs of the last frame (information properties of the proxy).
  vtkIdType GetNumberOfTetrahedra();
  vtkIdType GetNumberOfSkippedCells();
  double GetLastRenderSeconds();
  double GetLastSortSeconds();
  double GetLastPreIntegrationSeconds();
  vtkIdType GetLastSortCycles();
  vtkIdType GetNumberOfIntermixedVolumes();
  vtkIdType GetNumberOfIntermixedTetrahedra();
  /// How the last frame was drawn and how that way was chosen (vtkPsiVolumeMapper::GetLastDrawWay).
  const char* GetLastDrawWay();
#ifndef __VTK_WRAP__
  /// All of the above at once (vtkPsiFrameStatsInformation gathers it over the processes).
  psi::FrameStats GetFrameStats() const;
#endif
  ///@}

protected:
  vtkPsiVolumeRepresentation();
  ~vtkPsiVolumeRepresentation() override;

  /// Non-tetrahedral input is tetrahedralized conformingly first. ParaView does not call the
  /// mapper for empty input; its read-outs are reset here instead.
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// Chooses what this render draws while the camera moves, and builds the level of detail when
  /// it is stale (vtkPsiVolumeRepresentationInteraction.cxx).
  void ChooseInteractiveImage(vtkInformation* inInfo);
  int UpdateUnusedSurfaceLOD(vtkInformation* inInfo, vtkInformation* outInfo);
  bool UpdateVolumeLOD(vtkInformation* inInfo, vtkPVRenderView* view);
  void InstallLODMapper(bool volume);

  vtkNew<vtkPsiVolumeMapper> PsiMapper;
  vtkNew<vtkPsiConformingTetrahedralize> Conforming;
  bool TetrahedralizeInput = false;
#ifndef __VTK_WRAP__
  std::unique_ptr<PsiLevelOfDetail> LOD;
  psi::InteractionSettings Interaction;
#endif
  bool VolumeLODInstalled = false;
  int LastInteractiveImage = -1;

private:
  vtkPsiVolumeRepresentation(const vtkPsiVolumeRepresentation&) = delete;
#ifndef __VTK_WRAP__
  template <typename Setter, typename... Values>
  void Forward(Setter set, Values... values);
  void SetInteraction(psi::Setting id, double value);
#endif
  void operator=(const vtkPsiVolumeRepresentation&) = delete;
};

#endif
