#include "PsiDepthPeelingCalls.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkVolume.h"

namespace
{
// The dual depth peeling pass among the render passes listed in the volume's property keys,
// when it peels volumes too.
bool PeelsVolumes(vtkInformation* keys)
{
  if (!keys || !keys->Has(vtkOpenGLRenderPass::RenderPasses()))
  {
    return false;
  }
  const int n = keys->Length(vtkOpenGLRenderPass::RenderPasses());
  for (int i = 0; i < n; ++i)
  {
    auto* pass =
      vtkDualDepthPeelingPass::SafeDownCast(keys->Get(vtkOpenGLRenderPass::RenderPasses(), i));
    if (pass && pass->GetVolumetricPass())
    {
      return true;
    }
  }
  return false;
}
} // namespace

bool PsiDepthPeelingCalls::DrawThisCall(vtkVolume* vol)
{
  vtkInformation* keys = vol->GetPropertyKeys();
  this->Peeling = PeelsVolumes(keys);
  if (!this->Peeling)
  {
    return true;
  }
  const vtkMTimeType t = keys->GetMTime();
  const bool first = t != this->FrameKeysTime;
  this->FrameKeysTime = t;
  return first;
}
