// PsiParallel: runs work that uses vtkSMPTools on threads even where the process-wide backend is
// Sequential. Debian's ParaView 5.11 defaults vtkSMPTools to the Sequential backend (STDThread is
// built in): the sorts run their own loops with STDThread in a local scope, leaving the
// process-wide choice to ParaView.
//
// VTK 9.2's backend choice is process-wide, and a vtkSMPTools loop reads it again for its
// thread-local scratch: a switch while a loop runs on another thread would hand that loop's
// scratch from one backend to the other. So while work runs on a thread of its own
// (BackgroundWork, e.g. the interactive level of detail's resampling), Parallel runs its work
// under the backend as it is, without switching.
#ifndef PsiParallel_h
#define PsiParallel_h

#include "PsiVolumeCoreModule.h"

#include "vtkSMPTools.h"

#include <string>

namespace psi
{

/// Marks, for its lifetime, work running on a thread other than the main one that uses
/// vtkSMPTools.
class PSIVOLUMECORE_EXPORT BackgroundWork
{
public:
  BackgroundWork();
  ~BackgroundWork();
  BackgroundWork(const BackgroundWork&) = delete;
  BackgroundWork& operator=(const BackgroundWork&) = delete;
  /// Whether any such work runs now.
  static bool Running();
};

template <typename F>
void Parallel(F&& work)
{
  if (!BackgroundWork::Running() && vtkSMPTools::GetBackend() &&
    std::string(vtkSMPTools::GetBackend()) == "Sequential")
  {
    vtkSMPTools::Config config;
    config.Backend = "STDThread";
    vtkSMPTools::LocalScope(config, work);
  }
  else
  {
    work();
  }
}

} // namespace psi

#endif
