// PsiShaderParameters: the camera of one frame and the uniforms that do not belong to a GPU
// table (those are set by each table's Activate, PsiGpuTable.h): camera matrices, pixel rays,
// isosurfaces with the scene's lights. One named step per concern, as
// vtkOpenGLGPUVolumeRayCastMapper's SetCameraShaderParameters and its siblings.
#ifndef PsiShaderParameters_h
#define PsiShaderParameters_h

#include "PsiIsosurfaceList.h"

#include <array>
#include <utility>
#include <vector>

class vtkRenderer;
class vtkShaderProgram;
class vtkVolume;
class vtkVolumeProperty;

struct PsiFrameCamera
{
  double MCVC[16]; ///< model (shifted mesh) -> view, row-major
  double View[16]; ///< world -> view, row-major
  double VCDC[16]; ///< view -> clip, row-major
  double DCVC[16]; ///< its inverse
  bool Parallel = false;
  double NearZ = 0; ///< view-space z of the near plane (negative)

  /// The camera of `ren` for the mesh of `vol` shifted by `shift` (psi::TetMesh::Shift).
  static PsiFrameCamera FromRenderer(vtkRenderer* ren, vtkVolume* vol, const double shift[3]);
  /// Whether the near plane cuts the box `bounds` (mesh coordinates): then cells crossing it
  /// need the near-clipping path.
  bool NearPlaneCuts(const double bounds[6]) const;
};

/// MCVCMatrix, VCDCMatrix, DCVCMatrix, nearZ, parallelProjection.
void SetCameraShaderParameters(vtkShaderProgram* program, const PsiFrameCamera& camera);

/// pixelRayOrigin and pixelRayStep (psi::PixelRaysOf) for a target of `size` pixels: the
/// silhouettes' fragments form their rays from them (PsiRaySegmentsFS.glsl).
void SetPixelRayShaderParameters(
  vtkShaderProgram* program, const PsiFrameCamera& camera, const int size[2]);

/// coverExtraMax: the area, in NDC units, by which one covering triangle may exceed a quad
/// silhouette (PsiProjectionClassesGS.glsl emitQuadCover), PsiSilhouetteCoverPixels pixels of a
/// target of `size` pixels.
void SetSilhouetteShaderParameters(vtkShaderProgram* program, const int size[2]);

/// Pixels of extra coverage worth one triangle less. A silhouette drawn as one triangle instead
/// of two halves llvmpipe's per-triangle setup, binning and rasterization, which dominate for
/// small cells; the extra fragments see an empty segment and are discarded. Without a bound,
/// meshes with large cells lose what small ones gain (docs/decisions.md, "Silhouettes").
constexpr double PsiSilhouetteCoverPixels = 32.0;

struct PsiIsosurfaceStyle
{
  bool UseColorMap = true;       ///< color each surface through the color map at its value
  double Color[3] = { 1, 1, 1 }; ///< otherwise this solid color
  bool Lighting = true;
  bool Smooth = true; ///< interpolated point gradients (needs normalMatrix)
  int MaxLights = 8;
  /// The color map's color of each isovalue, given (several volumes intermixed: each volume's
  /// own map, PsiIntermixedScene::IsoColors); nullptr: the property's color map at the value.
  const std::vector<std::pair<double, std::array<double, 3>>>* ValueColors = nullptr;
};

/// isoValues (fractions of `scalarRange`, as the mesh's scalars: psi::TetMesh::Points4),
/// isoColors, isoOpacities, isoLighting, the lights (lightCount, lightDirVC, lightColor) and,
/// for smooth shading, normalMatrix.
void SetIsosurfaceShaderParameters(vtkShaderProgram* program, const psi::IsosurfaceList& list,
  const double scalarRange[2], const PsiIsosurfaceStyle& style, vtkVolumeProperty* property,
  vtkRenderer* ren, const PsiFrameCamera& camera);

#endif
