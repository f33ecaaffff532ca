// psi::Stopwatch: the seconds since it was made, on std::chrono::steady_clock (monotonic, so a
// clock adjustment never makes a negative time). The one clock of every timing the read-outs and
// the frame statistics report: table builds, sorts, frames, level-of-detail builds and draws.
#ifndef PsiStopwatch_h
#define PsiStopwatch_h

#include <chrono>

namespace psi
{

class Stopwatch
{
public:
  /// Seconds since construction.
  double Seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
  }

private:
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
};

} // namespace psi

#endif
