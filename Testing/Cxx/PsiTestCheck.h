// Minimal checking for the C++ tests: each CHECK prints what failed; main reports and returns
// whether any did.
#ifndef PsiTestCheck_h
#define PsiTestCheck_h

#include <cstdio>
#include <cstdlib>
#include <string>

namespace psitest
{
inline int& Failures()
{
  static int n = 0;
  return n;
}

/// The projector a run asks for through PSI_PROJECTOR ("geometry" or "compute"; CTest runs each
/// render test once with each): 0 geometry shader, 1 compute shader (vtkPsiVolumeMapper's
/// Projectors), -1 when unset.
inline int RequestedProjector()
{
  const char* p = std::getenv("PSI_PROJECTOR");
  return !p ? -1 : std::string(p) == "compute" ? 1 : std::string(p) == "geometry" ? 0 : -1;
}
} // namespace psitest

#define PSI_CHECK(cond, ...)                                                                       \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      ++psitest::Failures();                                                                       \
      std::printf("FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond);                              \
      std::printf(__VA_ARGS__);                                                                    \
      std::printf("\n");                                                                           \
    }                                                                                              \
  } while (0)

namespace psitest
{
/// Checks that the last frame used the projector PSI_PROJECTOR asks for (`used`: the mapper's
/// GetLastUsedProjector()).
inline void CheckRequestedProjector(int used)
{
  PSI_CHECK(RequestedProjector() < 0 || used == RequestedProjector(),
    "the last frame used projector %d, not the one asked for (PSI_PROJECTOR)", used);
}

/// Prints "<test> passed" or "<test> FAILED"; the exit code of the test's main.
inline int Report(const char* test)
{
  std::printf("%s %s\n", test, Failures() ? "FAILED" : "passed");
  return Failures() ? 1 : 0;
}
} // namespace psitest

#endif
