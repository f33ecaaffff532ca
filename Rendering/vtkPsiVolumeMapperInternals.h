// vtkPsiVolumeMapper's parts (private to the mapper's own files): each owns one job of the frame
// and its GPU resources (docs/architecture.md).
#ifndef vtkPsiVolumeMapperInternals_h
#define vtkPsiVolumeMapperInternals_h

#include "vtkPsiVolumeMapper.h"

#include "PsiAdaptiveNodes.h"
#include "PsiComputeProjector.h"
#include "PsiDepthPeelingCalls.h"
#include "PsiDriverLimits.h"
#include "PsiGeometryProjector.h"
#include "PsiIntermixedScene.h"
#include "PsiMeasuredChoice.h"
#include "PsiMeshBuffers.h"
#include "PsiOpacityMasks.h"
#include "PsiRenderTarget.h"
#include "PsiSamplesPassed.h"
#include "PsiTableTextures.h"
#include "PsiVisibilityOrder.h"

#include "vtkSmartPointer.h"
#include "vtkVolume.h"

#include <cstdint>
#include <memory>
#include <string>

struct vtkPsiVolumeMapper::Internals
{
  PsiMeshBuffers Mesh;
  PsiVisibilityOrder Order;
  PsiLookupTextureSet Tables;
  PsiRenderTarget Target;
  PsiOpacityMasks Masks; // early ray termination of a front-to-back image
  PsiGeometryProjector Geometry;
  PsiComputeProjector Compute;
  PsiDepthPeelingCalls Peeling; // the depth-peeling stage of this call
  // The input and its modification time that vtkPsiVolumeMapper::GetBounds last measured.
  vtkDataSet* BoundsInput = nullptr;
  vtkMTimeType BoundsTime = 0;
  PsiSamplesPassed Samples; // the volume's samples that pass the depth test (testing aid)
  bool CountSamples = false;
  uint64_t SamplesPassed = 0; // counted over the last frame's draws
  // The volume's samples counted between these two calls, when asked (not the masks': one
  // GL_SAMPLES_PASSED query runs at a time).
  void StartCounting()
  {
    if (this->CountSamples)
    {
      this->Samples.Begin();
    }
  }
  void StopCounting()
  {
    this->Samples.End();
    this->SamplesPassed += this->Samples.Take();
  }
  // The way each frame draws, timed on the first frames under 'Auto' (PsiMeasuredChoice.h).
  psi::MeasuredChoice Choice;

  // Transfer-function nodes for adaptive sampling, for the property and range they came from.
  PsiAdaptiveNodes AdaptiveNodes;

  // Several volumes intermixed (vtkPsiVolumeMapperIntermixed.cxx): the mapper that draws them as
  // one mesh when this one draws a frame's intermixed volumes, its volume and the scene made for
  // it; on that mapper, the scene it draws instead of an input (nullptr: its own input).
  vtkSmartPointer<vtkPsiVolumeMapper> Union;
  vtkSmartPointer<vtkVolume> UnionVolume;
  std::unique_ptr<PsiIntermixedScene> Scene;
  const PsiIntermixedScene* Given = nullptr;

  PsiDriverLimits TestingLimits; // lowered limits for tests (SetDriverLimitsForTesting)
  /// The current context's buffer limits, lowered for tests.
  PsiDriverLimits Limits() const { return PsiDriverLimits::Query().LoweredTo(this->TestingLimits); }
  std::string LastWarning;
  std::string LastDrawError;   // said once per new text
  std::string LastFeatureNote; // what a separate opacity array changed, said once
  vtkWindow* Context = nullptr;

  void Release(vtkWindow* win)
  {
    if (this->Context)
    {
      this->Mesh.ReleaseGraphicsResources(win);
      this->Order.ReleaseGraphicsResources(win);
      this->Samples.ReleaseGraphicsResources();
    }
    this->Tables.ReleaseGraphicsResources(win);
    this->Peeling.ReleaseGraphicsResources(win);
    this->Target.ReleaseGraphicsResources(win);
    this->Masks.ReleaseGraphicsResources(win);
    this->Geometry.ReleaseGraphicsResources();
    this->Compute.ReleaseGraphicsResources(win);
    if (this->Union)
    {
      this->Union->ReleaseGraphicsResources(win);
    }
    this->Context = nullptr;
  }
};

#endif
