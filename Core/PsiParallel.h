// PsiParallel: runs work that uses vtkSMPTools on threads even where the process-wide backend is
// Sequential. Debian's ParaView 5.11 defaults vtkSMPTools to the Sequential backend (STDThread is
// built in): the sorts run their own loops with STDThread in a local scope, leaving the
// process-wide choice to ParaView.
#ifndef PsiParallel_h
#define PsiParallel_h

#include "vtkSMPTools.h"

#include <string>

namespace psi
{

template <typename F>
void Parallel(F&& work)
{
  if (vtkSMPTools::GetBackend() && std::string(vtkSMPTools::GetBackend()) == "Sequential")
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
