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

#include "PsiVolumeRepresentationsModule.h"
#include "PsiFrameStats.h"
#include "vtkNew.h"
#include "vtkUnstructuredGridVolumeRepresentation.h"

class vtkPsiConformingTetrahedralize;
class vtkPsiVolumeMapper;

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
  /// A psi::Method value: a row of psi::IntegrationMethodTable() (PsiIntegrationMethods.h).
  void SetIntegrationMethod(int method);
  int GetIntegrationMethod();
  ///@}

  ///@{
  /// See vtkPsiVolumeMapper::SetEarlyDiscard (HAPT §3.5).
  void SetEarlyDiscard(bool on);
  bool GetEarlyDiscard();
  ///@}

  ///@{
  /// See vtkPsiVolumeMapper::SortMethods.
  void SetSortMethod(int method);
  int GetSortMethod();
  ///@}

  ///@{
  /// See vtkPsiVolumeMapper::Projectors.
  void SetProjector(int projector);
  int GetProjector();
  /// See vtkPsiVolumeMapper::Decompositions.
  void SetDecomposition(int decomposition);
  int GetDecomposition();
  ///@}

  ///@{
  /// Isosurfaces and adaptive sampling: see vtkPsiVolumeMapper.
  void SetNumberOfIsosurfaces(int n);
  void SetIsosurfaceValue(int i, double value);
  void SetIsosurfaceOpacity(double opacity);
  void SetNumberOfIsosurfaceOpacities(int n);
  void SetIsosurfaceOpacityValue(int i, double opacity);
  void SetIsosurfaceColor(double r, double g, double b);
  void SetIsosurfaceUseColorMap(int on);
  /// psi::IsosurfaceShadings: 0 smooth, 1 flat (both lit by the view's lights), 2 unlit.
  void SetIsosurfaceShading(int shading);
  void SetIsosurfaceMethod(int method);
  int GetLastUsedIsosurfaceMethod();
  void SetAdaptiveSampling(int mode);
  int GetAdaptiveSampling();
  /// Nodes adaptive sampling used in the last frame (0: it was not used).
  int GetLastNumberOfAdaptiveNodes();
  ///@}

  ///@{
  /// Read-outs of the last frame (information properties of the proxy).
  vtkIdType GetNumberOfTetrahedra();
  vtkIdType GetNumberOfSkippedCells();
  double GetLastRenderSeconds();
  double GetLastSortSeconds();
  double GetLastPreIntegrationSeconds();
  vtkIdType GetLastSortCycles();
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

  vtkNew<vtkPsiVolumeMapper> PsiMapper;
  vtkNew<vtkPsiConformingTetrahedralize> Conforming;
  bool TetrahedralizeInput = false;

private:
  vtkPsiVolumeRepresentation(const vtkPsiVolumeRepresentation&) = delete;
#ifndef __VTK_WRAP__
  template <typename Setter, typename... Values>
  void Forward(Setter set, Values... values);
#endif
  void operator=(const vtkPsiVolumeRepresentation&) = delete;
};

#endif
