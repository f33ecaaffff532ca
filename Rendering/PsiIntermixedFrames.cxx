#include "PsiIntermixedFrames.h"

#include "vtkPsiVolumeMapper.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <map>

namespace
{
// Per renderer: its frames so far, and which mapper claimed which frame, for each kind of draw.
struct Frames
{
  unsigned long Frame = 0;
  unsigned long ClaimedFrame[2] = { 0, 0 };
  const void* Claimant[2] = { nullptr, nullptr };
};

std::map<const vtkRenderer*, Frames>& AllFrames()
{
  static std::map<const vtkRenderer*, Frames> frames;
  return frames;
}

void OnRendererEvent(vtkObject* caller, unsigned long event, void*, void*)
{
  const auto* ren = static_cast<const vtkRenderer*>(caller);
  if (event == vtkCommand::DeleteEvent)
  {
    AllFrames().erase(ren);
  }
  else
  {
    ++AllFrames()[ren].Frame;
  }
}

// The frames of `ren`, counted from the first call on (observers added once per renderer).
Frames& FramesOf(vtkRenderer* ren)
{
  auto found = AllFrames().find(ren);
  if (found != AllFrames().end())
  {
    return found->second;
  }
  vtkNew<vtkCallbackCommand> count;
  count->SetCallback(OnRendererEvent);
  ren->AddObserver(vtkCommand::StartEvent, count);
  ren->AddObserver(vtkCommand::DeleteEvent, count);
  Frames& frames = AllFrames()[ren];
  frames.Frame = 1; // this call's frame, started before the observer was there
  return frames;
}
} // namespace

std::vector<vtkVolume*> PsiIntermixedFrames::VisibleVolumes(vtkRenderer* ren)
{
  std::vector<vtkVolume*> visible;
  vtkVolumeCollection* volumes = ren ? ren->GetVolumes() : nullptr;
  if (!volumes)
  {
    return visible;
  }
  vtkCollectionSimpleIterator it;
  volumes->InitTraversal(it);
  while (vtkVolume* vol = volumes->GetNextVolume(it))
  {
    if (vol->GetVisibility())
    {
      visible.push_back(vol);
    }
  }
  return visible;
}

std::vector<PsiIntermixedMember> PsiIntermixedFrames::Members(vtkRenderer* ren)
{
  std::vector<PsiIntermixedMember> members;
  for (vtkVolume* vol : VisibleVolumes(ren))
  {
    auto* mapper = vtkPsiVolumeMapper::SafeDownCast(vol->GetMapper());
    if (mapper && !mapper->GetDrawnByStandIn() && mapper->GetInput() &&
      mapper->GetInput()->GetNumberOfCells() > 0)
    {
      members.push_back({ vol, mapper });
    }
  }
  return members;
}

const vtkPsiVolumeMapper* PsiIntermixedFrames::Claimant(vtkRenderer* ren)
{
  return static_cast<const vtkPsiVolumeMapper*>(FramesOf(ren).Claimant[0]);
}

bool PsiIntermixedFrames::Claim(vtkRenderer* ren, const void* mapper, Draws what)
{
  Frames& frames = FramesOf(ren);
  const int k = what == Draws::FullFrames ? 0 : 1;
  if (frames.ClaimedFrame[k] != frames.Frame)
  {
    frames.ClaimedFrame[k] = frames.Frame;
    frames.Claimant[k] = mapper;
  }
  return frames.Claimant[k] == mapper;
}
