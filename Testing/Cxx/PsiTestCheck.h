// Minimal checking for the C++ tests: each CHECK prints what failed; main returns the count.
#ifndef PsiTestCheck_h
#define PsiTestCheck_h

#include <cstdio>

namespace psitest
{
inline int& Failures()
{
  static int n = 0;
  return n;
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

#endif
