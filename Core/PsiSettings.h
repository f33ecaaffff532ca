// PsiSettings: every user setting of 'Psi Volume' in one GL-free type, the way VTK's abstract
// vtkProjectedTetrahedraMapper holds what its OpenGL subclass uses and pbrt makes each object
// from one parameter set. Here, and only here: the enumerations with one numbering (the values of
// XML/PsiVolumeRepresentation.xml's <Entry>s), the defaults (the XML's default_values, checked by
// TestSettings), the valid ranges, the clamp with its one warning, and where each 'Auto' is
// resolved. The representation forwards its properties to vtkPsiVolumeMapper, which holds a
// psi::Settings; the frame plan (PlanFrame) reads it.
#ifndef PsiSettings_h
#define PsiSettings_h

#include "PsiIsosurfaceList.h"
#include "PsiVolumeCoreModule.h"

#include <string>
#include <vector>

// Plain C++ for the mapper and the tests; VTK's wrappers need none of it.
#ifndef __VTK_WRAP__
namespace psi
{

/// Visibility order (SortMethod): MPVONC orders across shared faces (Williams 1992), exact for
/// convex meshes; the centroid sort is faster but wrong across some shared faces.
namespace Sorts
{
enum : int
{
  Centroid = 0,
  MPVONC = 1
};
}

/// Which stage projects the tetrahedra (Projector); see UsesComputeProjector for 'Auto'.
namespace Projectors
{
enum : int
{
  GeometryShader = 0, ///< one geometry-shader invocation per tetrahedron (Maximo et al. 2010 §3.2)
  ComputeShader = 1,  ///< a compute pass writes each chunk's triangles (OpenGL 4.3)
  Auto = 2
};
}

/// How each projection is drawn (Decomposition); see UsesSilhouettes for 'Auto'.
namespace Decompositions
{
enum : int
{
  Silhouette = 0, ///< the convex hull of the projected vertices, 1-2 triangles, exact segments
  Fan = 1,        ///< Shirley and Tuchman's 1-4 triangles, as HAPT draws them (Maximo et al. §3.2)
  Auto = 2
};
}

/// How isosurfaces are drawn (IsosurfaceMethod, Maximo et al. 2010 §3.4 names both); see
/// UsesMarchingTetrahedra for 'Auto'.
namespace IsosurfaceMethods
{
enum : int
{
  MarchingTetrahedra = 0, ///< each crossing cell's surface emitted by the geometry shader
  PerFragment = 1,        ///< every fragment finds the crossings on its own segment
  Auto = 2
};
}

/// Isosurface shading (IsosurfaceShading): smooth normals from the smoothed point gradients,
/// flat normals from each cell's gradient (Maximo et al. 2010 §3.4), both lit by the view's
/// lights; or unlit color.
namespace IsosurfaceShadings
{
enum : int
{
  Smooth = 0,
  Flat = 1,
  Unlit = 2
};
}

/// Adaptive transfer-function sampling (AdaptiveSampling, Moreland's dissertation §4.3); see
/// UsesAdaptiveSampling for 'Auto'.
namespace AdaptiveModes
{
enum : int
{
  Off = 0,
  On = 1,
  Auto = 2
};
}

/// What an interactive render (the camera moving) draws (InteractionMode); see UsesVolumeLOD.
namespace InteractionModes
{
enum : int
{
  Auto = 0,            ///< the volume level of detail when a still frame exceeds the budget
  VolumeLOD = 1,       ///< always the volume level of detail
  ParaViewSurface = 2, ///< ParaView's own choice: its surface level of detail past LODThreshold
  FullFrame = 3        ///< always the full 'Psi Volume' frame
};
}

/// What drew an interactive frame (the representation's LastInteractiveImage read-out).
namespace InteractiveImages
{
enum : int
{
  FullFrame = 0,      ///< the full 'Psi Volume' frame
  VolumeLOD = 1,      ///< the volume level of detail
  ParaViewSurface = 2 ///< ParaView's surface level of detail
};
}

/// Largest number of transfer-function nodes used for adaptive sampling (more are thinned).
constexpr int MaxAdaptiveNodes = 64;
/// Adaptive sampling adds nodes where a color map bends farther than this from linear
/// interpolation between its nodes (psi::SampleTransferFunctionNodes).
constexpr double AdaptiveNodeTolerance = 1.0 / 512;
/// 'Auto' samples adaptively when the sampled table misses the transfer function by more than
/// this at a node (psi::TableDeviation): a feature narrower than the table resolves.
constexpr double AdaptiveAutoDeviation = 1.0 / 255;

/// The user's settings, with their defaults. Integers outside their range are clamped by
/// SetClamped (with a warning), never here.
struct PSIVOLUMECORE_EXPORT Settings
{
  int IntegrationMethod = 1; ///< psi::Method (PsiIntegrationMethods.h): partial pre-integration
  int SortMethod = Sorts::MPVONC;
  int Projector = Projectors::Auto;
  int Decomposition = Decompositions::Auto;
  /// In perspective with the fan, each fragment's segment from the two face planes of its fan
  /// triangle instead of HAPT's screen-linear interpolation (exact only in parallel projection).
  bool ExactPerspectiveSegments = true;
  /// Drop cells whose scalar range sees zero opacity only (Maximo et al. 2010 §3.5).
  bool EarlyDiscard = true;
  int TransferFunctionSamples = 1024;
  int AdaptiveSampling = AdaptiveModes::Auto;

  std::vector<double> IsosurfaceValues; ///< as given: any order, duplicates allowed
  double IsosurfaceOpacity = 1;         ///< of every isovalue without its own opacity
  std::vector<double> IsosurfaceOpacities; ///< entry i: opacity of IsosurfaceValues[i]
  double IsosurfaceColor[3] = { 1, 1, 1 }; ///< when IsosurfaceUseColorMap is off
  bool IsosurfaceUseColorMap = true;
  int IsosurfaceMethod = IsosurfaceMethods::Auto;
  int IsosurfaceShading = IsosurfaceShadings::Smooth;

  int InteractionMode = InteractionModes::Auto;
  /// Seconds an interactive frame may take: 'Auto' draws the level of detail while the camera
  /// moves when the last still frame took longer (0.1 s keeps an interaction near 10 frames/s).
  double InteractiveBudget = 0.1;

  /// The isosurfaces to draw: the values normalized (psi::IsosurfaceList).
  IsosurfaceList Isosurfaces() const;
};

/// The settings with a range: integers (enumerations and counts) and reals.
enum class Setting
{
  IntegrationMethod,
  SortMethod,
  Projector,
  Decomposition,
  TransferFunctionSamples,
  AdaptiveSampling,
  IsosurfaceMethod,
  IsosurfaceShading,
  InteractionMode,
  IsosurfaceOpacity,
  InteractiveBudget,
  Count
};

/// One row of the table of ranged settings: its property name (the XML's), its member and its
/// valid range (an enumeration's values are all the integers from Min to Max).
struct SettingInfo
{
  Setting Id;
  const char* Name;
  int Settings::*Int;       ///< the member, for an integer setting (else null)
  double Settings::*Double; ///< the member, for a real setting (else null)
  double Min, Max;
  bool Property = true; ///< a property of the representation (XML); else the mapper's only
};

/// The table of ranged settings, one row per Setting, in its order.
PSIVOLUMECORE_EXPORT const std::vector<SettingInfo>& SettingTable();
PSIVOLUMECORE_EXPORT const SettingInfo& GetSettingInfo(Setting id);
/// The value of ranged setting `id` in `s` (an integer setting's as a double).
PSIVOLUMECORE_EXPORT double ValueOf(const Settings& s, Setting id);

/// Sets `id` in `s` to `value`, clamped to its range. Returns the warning for a value out of
/// range ("" otherwise), which names the setting, the value, the range and the value used.
PSIVOLUMECORE_EXPORT std::string SetClamped(Settings& s, Setting id, double value);

/// The boolean settings, by property name (for TestSettings).
struct BoolSettingInfo
{
  const char* Name;
  bool Settings::*Member;
  bool Property = true; ///< a property of the representation (XML); else the mapper's only
};
PSIVOLUMECORE_EXPORT const std::vector<BoolSettingInfo>& BoolSettingTable();

///@{
/// Where each 'Auto' is resolved.
/// The compute projector only when asked for: 'Auto' is the geometry shader, measured the faster
/// of the two with Mesa's llvmpipe (docs/decisions.md, "Projectors").
PSIVOLUMECORE_EXPORT bool UsesComputeProjector(const Settings& s);
/// Silhouettes unless the fan is asked for: 'Auto' is the silhouette, which draws half the
/// triangles and is the faster with llvmpipe (docs/decisions.md, "Silhouettes").
PSIVOLUMECORE_EXPORT bool UsesSilhouettes(const Settings& s);
/// Marching tetrahedra when asked for, or under 'Auto' when early discard applies (on, and the
/// opacity function has zero regions: plain contours, where only the surfaces and the visible
/// pieces are drawn); per fragment otherwise. The driver's geometry-shader limits may still
/// overrule it (PlanFrame).
PSIVOLUMECORE_EXPORT bool UsesMarchingTetrahedra(const Settings& s, bool zeroOpacity);
/// Adaptive sampling when on, or under 'Auto' when the sampled table misses the transfer
/// function's nodes by more than AdaptiveAutoDeviation (Moreland's dissertation §4.3).
PSIVOLUMECORE_EXPORT bool UsesAdaptiveSampling(const Settings& s, double tableDeviation);
/// Whether an interactive render draws the volume level of detail: always under 'Volume LOD',
/// under 'Auto' when the last still frame took longer than the interactive budget.
PSIVOLUMECORE_EXPORT bool UsesVolumeLOD(const Settings& s, double lastStillSeconds);
///@}

} // namespace psi
#endif // __VTK_WRAP__

#endif
