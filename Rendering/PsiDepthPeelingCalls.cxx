#include "PsiDepthPeelingCalls.h"

#include "PsiSceneQueries.h"

#include "vtkAbstractMapper.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"

#include <string>

namespace
{
// The dual depth peeling pass among the render passes listed in the volume's property keys,
// when it peels volumes too.
vtkDualDepthPeelingPass* VolumePeelingPass(vtkInformation* keys)
{
  if (!keys || !keys->Has(vtkOpenGLRenderPass::RenderPasses()))
  {
    return nullptr;
  }
  const int n = keys->Length(vtkOpenGLRenderPass::RenderPasses());
  for (int i = 0; i < n; ++i)
  {
    auto* pass =
      vtkDualDepthPeelingPass::SafeDownCast(keys->Get(vtkOpenGLRenderPass::RenderPasses(), i));
    if (pass && pass->GetVolumetricPass())
    {
      return pass;
    }
  }
  return nullptr;
}

// The stage, told by the samplers the pass declares for a volume's ray caster in it.
PsiDepthPeelingCalls::Stage ReplacedStage(
  vtkDualDepthPeelingPass* pass, vtkAbstractMapper* mapper, vtkVolume* vol)
{
  std::string vs, gs;
  std::string fs = "//VTK::DepthPeeling::Dec\n//VTK::CallWorker::Impl\n";
  pass->PreReplaceShaderValues(vs, gs, fs, mapper, vol);
  if (fs.find("depthRangeTex") != std::string::npos)
  {
    return PsiDepthPeelingCalls::AlphaBlend;
  }
  if (fs.find("lastFrontColorTex") != std::string::npos)
  {
    return PsiDepthPeelingCalls::Peel;
  }
  if (fs.find("innerDepthTex") != std::string::npos)
  {
    return PsiDepthPeelingCalls::OutsideLayers;
  }
  return PsiDepthPeelingCalls::Skip;
}
} // namespace

PsiDepthPeelingCalls::PsiDepthPeelingCalls() = default;
PsiDepthPeelingCalls::~PsiDepthPeelingCalls() = default;

PsiDepthPeelingCalls::Stage PsiDepthPeelingCalls::StageOf(vtkAbstractMapper* mapper, vtkVolume* vol)
{
  vtkInformation* keys = vol->GetPropertyKeys();
  this->Pass = VolumePeelingPass(keys);
  if (!this->Pass)
  {
    return this->LastStage = Plain;
  }
  const vtkMTimeType t = keys->GetMTime();
  const bool first = t != this->FrameKeysTime;
  this->FrameKeysTime = t;
  const Stage stage = ReplacedStage(this->Pass, mapper, vol);
  if (stage != Skip)
  {
    return this->LastStage = stage;
  }
  this->Pass = nullptr;
  return this->LastStage = first ? Plain : Skip;
}

void PsiDepthPeelingCalls::NoteTranslucentGeometry(vtkAbstractMapper* mapper, vtkRenderer* ren)
{
  const bool translucent = this->LastStage == Plain && psi::SceneHasTranslucentGeometry(ren);
  if (translucent && !this->NotedTranslucent)
  {
    vtkWarningWithObjectMacro(mapper,
      "Psi Volume: translucent geometry is drawn before volumes unless the view peels volumes "
      "too (ParaView: the view's DepthPeelingForVolumes; VTK: the renderer's UseDepthPeeling "
      "and UseDepthPeelingForVolumes); a surface in front of or inside the volume is then "
      "covered by it.");
  }
  this->NotedTranslucent = translucent;
}

void PsiDepthPeelingCalls::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper,
  vtkVolume* vol, vtkOpenGLRenderWindow* renWin)
{
  if (!this->Pass)
  {
    return;
  }
  if (!this->Placeholder->GetHandle())
  {
    const float texel[2] = { -1.0f, -1.0f };
    this->Placeholder->SetContext(renWin);
    this->Placeholder->Create2DFromRaw(1, 1, 2, VTK_FLOAT, const_cast<float*>(texel));
  }
  this->Placeholder->Activate();
  const int unit = this->Placeholder->GetTextureUnit();
  for (const char* name :
    { "outerDepthTex", "innerDepthTex", "lastFrontColorTex", "opaqueDepthTex", "depthRangeTex" })
  {
    program->SetUniformi(name, unit);
  }
  this->Pass->SetShaderParameters(program, mapper, vol, nullptr);
}

void PsiDepthPeelingCalls::Deactivate()
{
  this->Placeholder->Deactivate();
}

void PsiDepthPeelingCalls::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Placeholder->ReleaseGraphicsResources(win);
}
