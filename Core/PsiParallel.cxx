#include "PsiParallel.h"

#include <atomic>

namespace
{
std::atomic<int> BackgroundWorkCount{ 0 };
}

namespace psi
{
BackgroundWork::BackgroundWork()
{
  ++BackgroundWorkCount;
}

BackgroundWork::~BackgroundWork()
{
  --BackgroundWorkCount;
}

bool BackgroundWork::Running()
{
  return BackgroundWorkCount.load() > 0;
}
} // namespace psi
