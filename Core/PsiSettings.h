// PsiSettings: every user setting of 'Psi Volume' in GL-free types, the way VTK's abstract
// vtkProjectedTetrahedraMapper holds what its OpenGL subclass uses and pbrt makes each object
// from one parameter set. The scalar settings are declared once, in PsiSettingList.h; here are
// their typed enumerations (whose numbers are the values of XML/PsiVolumeRepresentation.xml's
// <Entry>s: numbers only at that edge), the types the list fills, the table of names and ranges,
// the clamp with its one warning, and where each 'Auto' is resolved. vtkPsiVolumeMapper holds a
// psi::Settings, which the frame plan (PlanFrame) reads; vtkPsiVolumeRepresentation holds the
// psi::InteractionSettings and forwards the rest to the mapper.
#ifndef PsiSettings_h
#define PsiSettings_h

#include "PsiIntegrationMethods.h"
#include "PsiIsosurfaceList.h"
#include "PsiSettingList.h"
#include "PsiVolumeCoreModule.h"

#include <string>
#include <vector>

// Plain C++ for the mapper and the tests; VTK's wrappers need none of it.
#ifndef __VTK_WRAP__
namespace psi
{

/// Visibility order (SortMethod): MPVONC orders across shared faces (Williams 1992), exact for
/// convex meshes; the centroid sort is faster but wrong across some shared faces.
enum class Sorts : int
{
  Centroid = 0,
  MPVONC = 1
};

/// Which stage projects the tetrahedra (Projector); see UsesComputeProjector for 'Auto'.
enum class Projectors : int
{
  GeometryShader = 0, ///< one geometry-shader invocation per tetrahedron (Maximo et al. 2010 §3.2)
  ComputeShader = 1,  ///< a compute pass writes each chunk's triangles (OpenGL 4.3)
  Auto = 2
};

/// Front-to-back compositing with early ray termination (EarlyRayTermination). 'Auto' draws
/// front to back where a pixel can turn opaque and times back to front against it on the
/// user's scene (psi::MeasuredChoice); 'On' draws front to back wherever the driver can mask
/// opaque pixels. The numbers keep a state file of the former on/off switch meaning the same:
/// its 'on' was 'Auto'.
enum class EarlyRayTerminations : int
{
  Off = 0,
  Auto = 1,
  On = 2
};

/// How each projection is drawn (Decomposition); see UsesSilhouettes for 'Auto'.
enum class Decompositions : int
{
  Silhouette = 0, ///< the convex hull of the projected vertices, 1-2 triangles, exact segments
  Fan = 1,        ///< Shirley and Tuchman's 1-4 triangles, as HAPT draws them (Maximo et al. §3.2)
  Auto = 2
};

/// How isosurfaces are drawn (IsosurfaceMethod, Maximo et al. 2010 §3.4 names both); see
/// UsesMarchingTetrahedra for 'Auto'.
enum class IsosurfaceMethods : int
{
  MarchingTetrahedra = 0, ///< each crossing cell's surface emitted by the geometry shader
  PerFragment = 1,        ///< every fragment finds the crossings on its own segment
  Auto = 2
};

/// Isosurface shading (IsosurfaceShading): smooth normals from the smoothed point gradients,
/// flat normals from each cell's gradient (Maximo et al. 2010 §3.4), both lit by the view's
/// lights; or unlit color.
enum class IsosurfaceShadings : int
{
  Smooth = 0,
  Flat = 1,
  Unlit = 2
};

/// Adaptive transfer-function sampling (AdaptiveSampling, Moreland's dissertation §4.3); see
/// UsesAdaptiveSampling for 'Auto'.
enum class AdaptiveModes : int
{
  Off = 0,
  On = 1,
  Auto = 2
};

/// What an interactive render (the camera moving) draws (InteractionMode); see UsesVolumeLOD.
enum class InteractionModes : int
{
  Auto = 0,            ///< the volume level of detail when a still frame exceeds the budget
  VolumeLOD = 1,       ///< always the volume level of detail
  ParaViewSurface = 2, ///< ParaView's own choice: its surface level of detail past LODThreshold
  FullFrame = 3        ///< always the full 'Psi Volume' frame
};

/// What drew an interactive frame (the representation's LastInteractiveImage read-out).
enum class InteractiveImages : int
{
  FullFrame = 0,      ///< the full 'Psi Volume' frame
  VolumeLOD = 1,      ///< the volume level of detail
  ParaViewSurface = 2 ///< ParaView's surface level of detail
};

/// Largest number of transfer-function nodes used for adaptive sampling (more are thinned).
constexpr int MaxAdaptiveNodes = 64;
/// Adaptive sampling adds nodes where a color map bends farther than this from linear
/// interpolation between its nodes (psi::SampleTransferFunctionNodes).
constexpr double AdaptiveNodeTolerance = 1.0 / 512;
/// 'Auto' samples adaptively when the sampled table misses the transfer function by more than
/// this at a node (psi::TableDeviation): a feature narrower than the table resolves.
constexpr double AdaptiveAutoDeviation = 1.0 / 255;

#define PSI_SETTING_MEMBER_ENUM(Name, Type, Default, Last) Type Name = Type::Default;
#define PSI_SETTING_MEMBER_NUMBER(Name, Type, Default, Min, Max, Where) Type Name = Default;
#define PSI_SETTING_MEMBER_BOOL(Name, Default, Where) bool Name = Default;

/// What the mapper draws with: the members of PSI_RENDER_SETTINGS with their defaults, and the
/// isosurfaces. Values outside their range are clamped by SetClamped (with a warning), never here.
struct PSIVOLUMECORE_EXPORT Settings
{
  PSI_RENDER_SETTINGS(PSI_SETTING_MEMBER_ENUM, PSI_SETTING_MEMBER_NUMBER, PSI_SETTING_MEMBER_BOOL)

  std::vector<double> IsosurfaceValues;    ///< as given: any order, duplicates allowed
  std::vector<double> IsosurfaceOpacities; ///< entry i: opacity of IsosurfaceValues[i]
  double IsosurfaceColor[3] = { 1, 1, 1 }; ///< when IsosurfaceUseColorMap is off

  /// The isosurfaces to draw: the values normalized (psi::IsosurfaceList).
  IsosurfaceList Isosurfaces() const;
};

/// What the representation draws while the camera moves: the members of
/// PSI_INTERACTION_SETTINGS with their defaults.
struct PSIVOLUMECORE_EXPORT InteractionSettings
{
  PSI_INTERACTION_SETTINGS(
    PSI_SETTING_MEMBER_ENUM, PSI_SETTING_MEMBER_NUMBER, PSI_SETTING_MEMBER_BOOL)
};

#define PSI_SETTING_ENUMERATOR(Name, ...) Name,
/// Every scalar setting, in the lists' order.
enum class Setting
{
  PSI_RENDER_SETTINGS(PSI_SETTING_ENUMERATOR, PSI_SETTING_ENUMERATOR, PSI_SETTING_ENUMERATOR)
    PSI_INTERACTION_SETTINGS(PSI_SETTING_ENUMERATOR, PSI_SETTING_ENUMERATOR, PSI_SETTING_ENUMERATOR)
      Count
};

/// The kind of a setting's values.
enum class SettingKind
{
  Enumeration, ///< a typed enumeration; the XML's numbers Min..Max
  Integer,
  Real,
  Boolean
};

/// One row of the settings table: its property name (the XML's), kind, default and valid
/// range (an enumeration's values are all the integers from Min to Max; a boolean's 0 and 1).
struct SettingInfo
{
  Setting Id;
  const char* Name;
  SettingKind Kind;
  double Default, Min, Max;
  bool Property;    ///< a property of the representation (XML); else the mapper's only
  bool Interaction; ///< a member of InteractionSettings; else of Settings
};

/// The table of settings, one row per Setting, in its order.
PSIVOLUMECORE_EXPORT const std::vector<SettingInfo>& SettingTable();
PSIVOLUMECORE_EXPORT const SettingInfo& GetSettingInfo(Setting id);
/// The value of setting `id` (an enumeration's as its number, a boolean's as 0 or 1); NaN for a
/// setting of the other struct.
PSIVOLUMECORE_EXPORT double ValueOf(const Settings& s, Setting id);
PSIVOLUMECORE_EXPORT double ValueOf(const InteractionSettings& s, Setting id);

///@{
/// Sets `id` to `value`, clamped to its range. Returns the warning for a value out of range or
/// not a whole number for an integer ("" otherwise), which names the setting, the value, the
/// range and the value used. A setting of the other struct is left alone, with a warning.
PSIVOLUMECORE_EXPORT std::string SetClamped(Settings& s, Setting id, double value);
PSIVOLUMECORE_EXPORT std::string SetClamped(InteractionSettings& s, Setting id, double value);
///@}

/// What a setter did: whether the value changed, and SetClamped's warning.
struct SettingChange
{
  bool Changed = false;
  std::string Warning;
};
///@{
/// SetClamped, telling whether the value changed: what a setter needs to warn and to mark itself
/// modified.
PSIVOLUMECORE_EXPORT SettingChange Change(Settings& s, Setting id, double value);
PSIVOLUMECORE_EXPORT SettingChange Change(InteractionSettings& s, Setting id, double value);
///@}

///@{
/// Where each 'Auto' is resolved.
/// The compute projector when asked for. 'Auto' starts with the geometry shader, usually the
/// faster with Mesa's llvmpipe (docs/decisions.md, "Projectors"); the plan opens the compute
/// projector to timing (PlanFrame, psi::MeasuredChoice).
PSIVOLUMECORE_EXPORT bool UsesComputeProjector(const Settings& s);
/// Silhouettes unless the fan is asked for. 'Auto' starts with the silhouette, which draws half
/// the triangles (docs/decisions.md, "Silhouettes"); the plan opens the fan to timing.
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
PSIVOLUMECORE_EXPORT bool UsesVolumeLOD(const InteractionSettings& s, double lastStillSeconds);
///@}

} // namespace psi
#endif // __VTK_WRAP__

#endif
