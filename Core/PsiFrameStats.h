// PsiFrameStats: what one 'Psi Volume' frame did, as one value shared by the mapper (which fills
// it), the representation, the information object that gathers it over MPI ranks, and the
// properties panel's read-out.
#ifndef PsiFrameStats_h
#define PsiFrameStats_h

#include <algorithm>
#include <cstdint>

namespace psi
{
struct FrameStats
{
  int64_t NumberOfTetrahedra = 0;   ///< drawn (summed over processes)
  int64_t NumberOfSkippedCells = 0; ///< non-tetrahedra, non-finite scalars (summed)
  int64_t LastSortCycles = 0;       ///< cycles MPVONC had to break (summed)
  double LastRenderSeconds = 0;     ///< CPU seconds of the Render call (largest)
  double LastSortSeconds = 0;       ///< of the visibility sort (largest)
  double LastPreIntegrationSeconds = 0; ///< of the last full pre-integration rebuild (largest)

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
  }
};
} // namespace psi

#endif
