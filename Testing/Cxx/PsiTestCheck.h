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

/// The settings a render test's command line asks for (CTest runs each render test once per
/// projector, some also with the fan): psi::Projectors and psi::Decompositions values, -1 when
/// not asked.
struct RequestedSettings
{
  int Projector = -1;
  int Decomposition = -1;
  /// --part NAME: the part of a test's checks to run (a test split into several CTest tests,
  /// each compiling its own shader programs); empty: all of them.
  std::string Part;
};

inline RequestedSettings& Requested()
{
  static RequestedSettings r;
  return r;
}

/// Reads `[IMAGE_FOLDER] [--projector geometry|compute] [--decomposition silhouette|fan]
/// [--part NAME]` into Requested() and returns the image folder ("" when none: no images are
/// written).
inline std::string ParseArguments(int argc, char* argv[])
{
  std::string folder;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const std::string value = i + 1 < argc ? argv[i + 1] : "";
    if (a == "--projector")
    {
      Requested().Projector = value == "compute" ? 1 : 0;
      ++i;
    }
    else if (a == "--decomposition")
    {
      Requested().Decomposition = value == "fan" ? 1 : 0;
      ++i;
    }
    else if (a == "--part")
    {
      Requested().Part = value;
      ++i;
    }
    else
    {
      folder = a;
    }
  }
  return folder;
}

/// Whether the command line asked for the part `name` of a test's checks, or for all of them.
inline bool RunsPart(const std::string& name)
{
  return Requested().Part.empty() || Requested().Part == name;
}

/// Gives `mapper` the projector and decomposition the command line asked for.
template <typename Mapper>
void ApplyRequested(Mapper* mapper)
{
  if (Requested().Projector >= 0)
  {
    mapper->SetProjector(Requested().Projector);
  }
  if (Requested().Decomposition >= 0)
  {
    mapper->SetDecomposition(Requested().Decomposition);
  }
}

/// The projector the command line asked for, -1 when none.
inline int RequestedProjector()
{
  return Requested().Projector;
}
} // namespace psitest

#define PSI_CHECK(cond, ...)                                                                       \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      ++psitest::Failures();                                                                       \
      std::printf("FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond);                                \
      std::printf(__VA_ARGS__);                                                                    \
      std::printf("\n");                                                                           \
    }                                                                                              \
  } while (0)

namespace psitest
{
/// Checks that the last frame used the projector the command line asked for (`used`: the
/// mapper's GetLastUsedProjector()).
inline void CheckRequestedProjector(int used)
{
  PSI_CHECK(RequestedProjector() < 0 || used == RequestedProjector(),
    "the last frame used projector %d, not the one asked for (--projector)", used);
}

/// Prints "<test> passed" or "<test> FAILED"; the exit code of the test's main.
inline int Report(const char* test)
{
  std::printf("%s %s\n", test, Failures() ? "FAILED" : "passed");
  return Failures() ? 1 : 0;
}
} // namespace psitest

#endif
