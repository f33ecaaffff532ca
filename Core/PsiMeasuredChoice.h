// PsiMeasuredChoice: the ways of drawing one frame that give the same image (within 1/255), and
// the choice among them by timing them on the user's own scene. Which way is fastest depends on
// the scene, not on a rule: early ray termination pays where many pixels turn opaque and costs
// where a few do (its masks are full-screen passes); the compute projector pays on some meshes
// and drivers and not on others. Under 'Auto' the first frames after anything that decides
// changes (the mesh, the transfer function, a setting, the view's size, the volume's projected
// size by more than ProjectedSizeRatio) time the alternatives one at a time, and the frames
// after them draw the fastest. A setting that is not 'Auto' leaves its alternative closed. The
// fan (Decomposition) is not an alternative: at isolated pixels it is not the silhouettes' image
// (docs/decisions.md). GL-free: the mapper gives the times (TestMeasuredChoice).
#ifndef PsiMeasuredChoice_h
#define PsiMeasuredChoice_h

#include "PsiVolumeCoreModule.h"

#include <limits>
#include <string>
#include <vector>

namespace psi
{
/// Front to back, the opacity masks a frame draws at first (PsiOpacityMasks::StrideTets), and
/// the alternative with a quarter of the full-screen passes, for scenes where few pixels turn
/// opaque.
constexpr int DefaultMasksPerFrame = 16;
constexpr int FewerMasksPerFrame = 4;

/// One way of drawing a frame; the alternatives 'Auto' times draw the same image within 1/255.
/// (The decomposition is not one of them: the fan is not the silhouettes' image at isolated
/// pixels, PlanFrame.)
struct DrawWay
{
  /// Front to back with early ray termination ("under"), else back to front ("over").
  bool FrontToBack = false;
  /// Front to back: opacity masks a frame at first.
  int MasksPerFrame = DefaultMasksPerFrame;
  bool ComputeProjector = false; ///< the compute pass, else the geometry shader
  bool operator==(const DrawWay& o) const
  {
    return this->FrontToBack == o.FrontToBack && this->MasksPerFrame == o.MasksPerFrame &&
      this->ComputeProjector == o.ComputeProjector;
  }
  bool operator!=(const DrawWay& o) const { return !(*this == o); }
  /// In words: "front to back (16 masks), geometry shader".
  std::string Describe() const;
};

/// The alternatives open to measurement: the setting is 'Auto' and the other way draws the
/// same image in this scene (PlanFrame decides).
struct DrawWayOptions
{
  bool Direction = false;     ///< back to front as well as front to back
  bool MasksPerFrame = false; ///< front to back: FewerMasksPerFrame as well
  bool Projector = false;     ///< the compute projector as well
  bool Any() const { return this->Direction || this->MasksPerFrame || this->Projector; }
  bool operator==(const DrawWayOptions& o) const
  {
    return this->Direction == o.Direction && this->MasksPerFrame == o.MasksPerFrame &&
      this->Projector == o.Projector;
  }
  bool operator!=(const DrawWayOptions& o) const { return !(*this == o); }
};

/// The fraction of a view (0..1) that the box `bounds` covers, from its eight corners
/// transformed by `modelToView` and `viewToClip` (row-major, VTK's order): the clamped
/// screen rectangle around them; 1 when a corner lies behind the eye.
PSIVOLUMECORE_EXPORT double ProjectedFraction(
  const double bounds[6], const double modelToView[16], const double viewToClip[16]);

class PSIVOLUMECORE_EXPORT MeasuredChoice
{
public:
  /// Frames timed for each way; the way's time is the shortest of them (its first frame may
  /// sort again for a new direction).
  static constexpr int FramesPerWay = 2;
  /// A projected size this many times larger or smaller than the one measured at measures again.
  static constexpr double ProjectedSizeRatio = 2;

  /// The way the coming frame draws. `decides`: everything besides the projected size that
  /// decides which way is fastest, as one string; `projectedPixels`: the volume's size on
  /// screen; `first`: the plan's way (each 'Auto' resolved to its default), where measurement
  /// starts; `open`: the alternatives. When `decides` or `open` or `first` changes, or the
  /// projected size by ProjectedSizeRatio, the measurement starts again.
  DrawWay Next(const std::string& decides, double projectedPixels, const DrawWay& first,
    const DrawWayOptions& open);
  /// The timed seconds of the frame that drew the way Next gave (ignored when not measuring).
  void Record(double seconds);

  bool IsMeasuring() const { return this->Measuring; }
  /// Ways timed since the measurement started, including the one being timed.
  int GetWaysTimed() const { return this->WaysTimed; }
  /// The fastest way found so far.
  const DrawWay& GetBest() const { return this->Best; }
  /// One line for the read-outs: "measuring (way 2)", "chosen by measurement of 4 ways" or
  /// "as set".
  std::string Describe() const;

private:
  enum class Dimension
  {
    Direction,
    MasksPerFrame,
    Projector
  };
  void Restart(const DrawWay& first);
  bool NextTrial();

  std::string Decides;
  double MeasuredPixels = 0;
  DrawWay First;
  DrawWayOptions Open;
  bool Started = false;
  bool Measuring = false;
  DrawWay Best, Trial;
  double BestSeconds = std::numeric_limits<double>::infinity();
  double TrialSeconds = std::numeric_limits<double>::infinity();
  int TrialFrames = 0;
  int WaysTimed = 0;
  std::vector<Dimension> Pending; ///< alternatives still to try, in order
};
} // namespace psi

#endif
