// PsiFrameStats: what one 'Psi Volume' frame did, as one value shared by the mapper (which fills
// it), the representation, the information object that gathers it over MPI ranks, and the
// properties panel's read-out.
#ifndef PsiFrameStats_h
#define PsiFrameStats_h

#include <algorithm>
#include <cstdint>
#include <string>

namespace psi
{
struct FrameStats
{
  int64_t NumberOfTetrahedra = 0;       ///< drawn (summed over processes)
  int64_t NumberOfSkippedCells = 0;     ///< non-tetrahedra, non-finite scalars (summed)
  int64_t LastSortCycles = 0;           ///< cycles MPVONC had to break (summed)
  double LastRenderSeconds = 0;         ///< CPU seconds of the frame's Render calls (largest)
  double LastSortSeconds = 0;           ///< of the visibility sort (largest)
  double LastPreIntegrationSeconds = 0; ///< of the last full pre-integration rebuild (largest)
  /// Several volumes intermixed: how many were drawn in one pass with this one (0: drawn alone;
  /// largest), and that combined draw's tetrahedra (summed).
  int64_t IntermixedVolumes = 0;
  int64_t IntermixedTetrahedra = 0;
  /// How the frame was drawn and how that way was chosen (psi::DrawWay::Describe and
  /// psi::MeasuredChoice::Describe; the first process's).
  std::string DrawWay;

  /// Combines another process's frame: counts add up, the slowest process sets the times.
  void Add(const FrameStats& o)
  {
    this->NumberOfTetrahedra += o.NumberOfTetrahedra;
    this->NumberOfSkippedCells += o.NumberOfSkippedCells;
    this->LastSortCycles += o.LastSortCycles;
    this->LastRenderSeconds = std::max(this->LastRenderSeconds, o.LastRenderSeconds);
    this->LastSortSeconds = std::max(this->LastSortSeconds, o.LastSortSeconds);
    this->LastPreIntegrationSeconds =
      std::max(this->LastPreIntegrationSeconds, o.LastPreIntegrationSeconds);
    this->IntermixedVolumes = std::max(this->IntermixedVolumes, o.IntermixedVolumes);
    this->IntermixedTetrahedra += o.IntermixedTetrahedra;
    this->DrawWay = this->DrawWay.empty() ? o.DrawWay : this->DrawWay;
  }
};

/// The seconds of a whole frame from the mapper's calls in it: under dual depth peeling VTK calls
/// a volume's mapper once per stage of every frame (PsiDepthPeelingCalls), and what 'Auto'
/// weighs against its budget is the frame, not its last stage.
struct FrameClock
{
  double Seconds = 0; ///< of the frame so far
  int Calls = 0;      ///< the calls that made it
  /// Adds one call; `startsFrame`: the call is a frame's first (not a later peeling stage).
  double Add(double seconds, bool startsFrame)
  {
    this->Seconds = startsFrame ? seconds : this->Seconds + seconds;
    this->Calls = startsFrame ? 1 : this->Calls + 1;
    return this->Seconds;
  }
};
} // namespace psi

#endif
