/**
 * @class   vtkPsiVolumeMapper
 * @brief   HAPT-style geometry-shader projected tetrahedra with selectable ray integration.
 *
 * Renders the tetrahedra of an unstructured grid (Maximo et al., HAPT, seed 002):
 *  - the mesh is uploaded once: points (xyz + scalar) as a texture buffer, tetrahedra as one
 *    uvec4 vertex attribute each; per frame only the visibility order (an index buffer) changes;
 *  - tetrahedra are drawn as GL_POINTS in back-to-front order (PsiVisibilitySort);
 *  - a geometry shader classifies each projection with the PTINT ternary truth table
 *    (PsiProjectionClasses) and emits 1-4 triangles carrying front scalar, back scalar, thickness;
 *  - a fragment shader integrates the segment (IntegrationMethod) into a floating-point target,
 *    clipped against the opaque geometry already drawn, which is then composited over the scene.
 *
 * Cell scalars are supported by giving each tetrahedron its own four points (constant scalar).
 * Cells that are not tetrahedra, and tetrahedra with a NaN/Inf scalar, are skipped and counted
 * (see GetNumberOfSkippedCells) with a warning naming the reason.
 */
#ifndef vtkPsiVolumeMapper_h
#define vtkPsiVolumeMapper_h

#include "PsiVolumeRepresentationsModule.h"
#include "vtkUnstructuredGridVolumeMapper.h"

#include <memory>

class vtkRenderer;
class vtkVolume;
class vtkWindow;

class PSIVOLUMEREPRESENTATIONS_EXPORT vtkPsiVolumeMapper : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkPsiVolumeMapper* New();
  vtkTypeMacro(vtkPsiVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Ray integration within each cell. Each is one GLSL function (Shaders/PsiIntegrate*.glsl).
  /// Numbered as psi::Method (PsiIntegrationMethods.h), which documents each.
  enum IntegrationMethods
  {
    AVERAGE = 0,                 ///< Shirley-Tuchman average luminance and attenuation
    PARTIAL_PRE_INTEGRATION = 1, ///< Moreland & Angel, Psi table (default)
    LINEAR_EXACT = 2,            ///< Williams-Max-Stein closed form (slow reference)
    AVERAGE_OPACITY = 3,         ///< average luminance and opacity
    LINEAR_LUMINANCE_AVERAGE_OPACITY = 4, ///< Moreland §5.3.1
    LINEAR_OPACITY_IMPROVED = 5, ///< Moreland §5.3.2
    FULL_PRE_INTEGRATION = 6,    ///< Roettger et al., 3D table per transfer function
    NUMBER_OF_INTEGRATION_METHODS
  };
  vtkSetClampMacro(IntegrationMethod, int, AVERAGE, NUMBER_OF_INTEGRATION_METHODS - 1);
  vtkGetMacro(IntegrationMethod, int);
  static const char* GetIntegrationMethodName(int method);

  /// In perspective, reconstruct each fragment's segment exactly from the two face planes of its
  /// fan triangle (default on) instead of HAPT's screen-linear interpolation of front scalar,
  /// back scalar and thickness, which is exact only in parallel projection (where it is used).
  vtkSetMacro(ExactPerspectiveSegments, bool);
  vtkGetMacro(ExactPerspectiveSegments, bool);
  vtkBooleanMacro(ExactPerspectiveSegments, bool);

  /// Visibility order: centroid sort (default) or MPVONC (Williams 1992), which orders across
  /// shared faces exactly (for convex meshes) using the mesh connectivity.
  enum SortMethods
  {
    CENTROID = 0,
    MPVONC = 1
  };
  vtkSetClampMacro(SortMethod, int, CENTROID, MPVONC);
  vtkGetMacro(SortMethod, int);

  /// Number of samples of the transfer function table (default 1024).
  vtkSetClampMacro(TransferFunctionSamples, int, 2, 1 << 16);
  vtkGetMacro(TransferFunctionSamples, int);

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

  ///@{
  /// What the last Render did: tetrahedra drawn, cells skipped (non-tetrahedra, non-finite
  /// scalars), CPU seconds spent sorting and in the whole call (GL work is asynchronous: call
  /// vtkRenderWindow::WaitForCompletion() before reading a wall-clock frame time).
  vtkGetMacro(NumberOfTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfSkippedCells, vtkIdType);
  vtkGetMacro(LastSortSeconds, double);
  /// Seconds spent rebuilding the full pre-integration table (last rebuild).
  vtkGetMacro(LastPreIntegrationSeconds, double);
  /// Cycles MPVONC had to break in the last sort.
  vtkGetMacro(LastSortCycles, vtkIdType);
  vtkGetMacro(LastRenderSeconds, double);
  /// Zeroes the read-outs above (no frame drawn, e.g. empty input).
  void ResetStatistics();
  /// Whether the last frame needed the near-plane path (camera inside or close to the mesh).
  vtkGetMacro(LastUsedNearPlaneClipping, bool);
  /// Whether the last frame clipped segments at opaque geometry overlapping the volume.
  vtkGetMacro(LastUsedOpaqueClipping, bool);
  ///@}

protected:
  vtkPsiVolumeMapper();
  ~vtkPsiVolumeMapper() override;

  int IntegrationMethod = PARTIAL_PRE_INTEGRATION;
  int TransferFunctionSamples = 1024;
  int SortMethod = CENTROID;
  double LastPreIntegrationSeconds = 0;
  vtkIdType LastSortCycles = 0;
  bool ExactPerspectiveSegments = true;
  vtkIdType NumberOfTetrahedra = 0;
  vtkIdType NumberOfSkippedCells = 0;
  double LastSortSeconds = 0;
  double LastRenderSeconds = 0;
  bool LastUsedNearPlaneClipping = false;
  bool LastUsedOpaqueClipping = false;

private:
  vtkPsiVolumeMapper(const vtkPsiVolumeMapper&) = delete;
  void operator=(const vtkPsiVolumeMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
