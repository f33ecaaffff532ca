// vtkPsiVolumeRepresentation while the camera moves: in each render the representation chooses
// what its vtkPVLODVolume draws (psi::UsesVolumeLOD decides 'Auto' from the last still frame's
// time), builds the volume level of detail (PsiLevelOfDetail) when it is stale, and reads out what
// drew the frame. The rest of the representation is in vtkPsiVolumeRepresentation.cxx.
#include "vtkPsiVolumeRepresentation.h"

#include "PsiCellPointBounds.h"
#include "PsiLODVolume.h"
#include "PsiLevelOfDetail.h"
#include "PsiSceneQueries.h"
#include "PsiSettings.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"
#include "vtkPVRenderViewDataDeliveryManager.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkVolumeProperty.h"

namespace
{
// Where this process samples the level of detail. In parallel, ParaView's ordered-compositing
// cuts of this render: one box per process, the same on every process, their union the bounds of
// the data ParaView balances (this mesh's, with other volumes' if shown), so the processes agree
// on one lattice without communicating (ranks may decide 'Auto' differently: no collective call
// here). Each process draws the bounds of its piece, not its cut: ParaView gives a cell that
// touches a cut to one process, so a piece may end a cell short of its cut or reach a cell past
// it, and the pieces abut where the cuts do not (ParaView 6.1, the test's slab cut at x = 0: the
// pieces [-16, -1] and [-1, 16]; the cut drew a gap a cell wide, mean 0.77/255 from the serial
// level of detail, max 70/255). Serially (or without cuts) the piece's own bounds.
PsiLevelOfDetail::Region LatticeRegion(vtkPVRenderView* view, vtkDataSet* piece)
{
  PsiLevelOfDetail::Region region;
  auto* manager =
    view ? vtkPVRenderViewDataDeliveryManager::SafeDownCast(view->GetDeliveryManager()) : nullptr;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  if (!manager || ranks < 2 || static_cast<int>(manager->GetCuts().size()) != ranks)
  {
    return region;
  }
  const std::vector<vtkBoundingBox>& cuts = manager->GetCuts();
  const vtkBoundingBox& own = cuts[controller->GetLocalProcessId()];
  vtkBoundingBox all;
  for (const vtkBoundingBox& cut : cuts)
  {
    all.AddBox(cut);
  }
  region.Parallel = own.IsValid() && all.IsValid() && piece;
  if (region.Parallel && !psi::CellPointBounds(piece, region.Box))
  {
    piece->GetBounds(region.Box); // no cell: the box crops nothing of an empty image
  }
  all.GetBounds(region.Global);
  return region;
}
} // namespace

int vtkPsiVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (request_type == vtkPVView::REQUEST_UPDATE_LOD() &&
    this->Interaction.InteractionMode != psi::InteractionModes::ParaViewSurface)
  {
    return this->UpdateUnusedSurfaceLOD(inInfo, outInfo);
  }
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_RENDER())
  {
    this->ChooseInteractiveImage(inInfo);
  }
  return 1;
}

// ParaView asks for its surface level of detail when the data is larger than its LODThreshold
// (the GUI's default is 20 MB): the surface of the whole mesh, which 'Psi Volume' draws only in
// 'ParaView surface' mode. Otherwise the superclass makes an outline instead (its bounds, at no
// cost), where the surface of a 2.56M-tetrahedron mesh took 4.7 s and 228 MB.
int vtkPsiVolumeRepresentation::UpdateUnusedSurfaceLOD(
  vtkInformation* inInfo, vtkInformation* outInfo)
{
  const bool outline = inInfo->Has(vtkPVRenderView::USE_OUTLINE_FOR_LOD()) != 0;
  inInfo->Set(vtkPVRenderView::USE_OUTLINE_FOR_LOD(), 1);
  const int ok =
    this->Superclass::ProcessViewRequest(vtkPVView::REQUEST_UPDATE_LOD(), inInfo, outInfo);
  if (!outline)
  {
    inInfo->Remove(vtkPVRenderView::USE_OUTLINE_FOR_LOD());
  }
  return ok;
}

// The superclass has set the actor's LOD from ParaView's LODThreshold (USE_LOD); every mode but
// 'ParaView surface' replaces that choice: the volume level of detail in interactive renders
// when the settings call for it, else the full frame. A still render (and so a screenshot, unless
// the view takes screenshots with interactive renders) is always the full frame.
void vtkPsiVolumeRepresentation::ChooseInteractiveImage(vtkInformation* inInfo)
{
  vtkPVRenderView* view = vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
  const bool interactive = view && psi::IsInteractiveRender(view->GetRenderWindow()) &&
    !view->GetUseInteractiveRenderingForScreenshots();
  const psi::InteractionSettings& s = this->Interaction;
  const bool surface = s.InteractionMode == psi::InteractionModes::ParaViewSurface;
  this->InstallLODMapper(!surface);
  if (!this->Actor->GetMapper())
  {
    // the superclass draws nothing for this piece (not an unstructured grid): neither does the
    // level of detail, which the actor would otherwise select
    this->LOD->Reset();
  }
  bool lod = false;
  if (surface)
  {
    lod = this->Actor->GetEnableLOD() != 0;
  }
  else
  {
    lod = interactive && psi::UsesVolumeLOD(s, this->PsiMapper->GetLastStillSeconds()) &&
      this->UpdateVolumeLOD(inInfo, view);
    this->Actor->SetEnableLOD(lod ? 1 : 0);
  }
  // the level of detail drawn in the full frame's place: not intermixed with other volumes' full
  // frames too
  this->PsiMapper->SetDrawnByStandIn(lod);
  if (interactive)
  {
    this->LastInteractiveImage = static_cast<int>(!lod ? psi::InteractiveImages::FullFrame
        : surface                                      ? psi::InteractiveImages::ParaViewSurface
                                                       : psi::InteractiveImages::VolumeLOD);
  }
}

// The actor's low level of detail: the volume one, or the superclass's surface mapper.
void vtkPsiVolumeRepresentation::InstallLODMapper(bool volume)
{
  if (volume == this->VolumeLODInstalled)
  {
    return;
  }
  if (volume)
  {
    this->Actor->SetLODMapper(this->LOD->GetMapper());
  }
  else
  {
    this->Actor->SetLODMapper(this->LODMapper.GetPointer());
  }
  this->VolumeLODInstalled = volume;
}

// Builds the level of detail from the piece this process draws when the piece, the scalar the
// full frame draws (array, association, component) or the region changed, reporting progress
// through ParaView's progress bar. False: nothing to draw (no piece, an empty one, or no
// array), or the build failed (one warning; the full frame is drawn instead).
//
// The build runs now, in the first interactive render that needs it, on every process: it takes
// a fraction of a still frame (docs/decisions.md "Interaction"), and in ordered compositing every
// process must draw the same kind of image in one frame.
bool vtkPsiVolumeRepresentation::UpdateVolumeLOD(vtkInformation* inInfo, vtkPVRenderView* view)
{
  vtkAlgorithmOutput* port = vtkPVRenderView::GetPieceProducer(inInfo, this);
  vtkDataSet* piece = port && port->GetProducer()
    ? vtkDataSet::SafeDownCast(port->GetProducer()->GetOutputDataObject(port->GetIndex()))
    : nullptr;
  const PsiLevelOfDetail::Scalars scalars =
    psi::LODScalarsOf(this->PsiMapper, this->Property, piece);
  const PsiLevelOfDetail::Region region = LatticeRegion(view, piece);
  if (this->LOD->NeedsUpdate(piece, scalars, region))
  {
    this->SetProgressText("Psi Volume: interactive level of detail");
    this->UpdateProgress(0.0);
    this->LOD->Update(piece, scalars, region, PsiLevelOfDetail::DefaultResolution,
      [this](double done) { this->UpdateProgress(done); });
    this->UpdateProgress(1.0);
    const std::string error = this->LOD->TakeNewError();
    if (!error.empty())
    {
      vtkWarningMacro("Psi Volume: the interactive level of detail could not be built ("
        << error << "); interactive renders draw full frames.");
    }
  }
  if (auto* actor = PsiLODVolume::SafeDownCast(this->Actor))
  {
    actor->UpdateLowLODVolumeProperty(); // after a transfer-function edit
  }
  if (vtkCamera* camera = view ? view->GetActiveCamera() : nullptr)
  {
    double direction[3];
    camera->GetDirectionOfProjection(direction);
    this->LOD->SetViewDirection(direction);
  }
  return this->LOD->HasImage();
}

double vtkPsiVolumeRepresentation::GetLastInteractiveSeconds()
{
  switch (static_cast<psi::InteractiveImages>(this->LastInteractiveImage))
  {
    case psi::InteractiveImages::FullFrame:
      return this->PsiMapper->GetLastRenderSeconds();
    case psi::InteractiveImages::VolumeLOD:
      return this->LOD->GetLastDrawSeconds();
    default:
      return 0;
  }
}

double vtkPsiVolumeRepresentation::GetLODBuildSeconds()
{
  return this->LOD->GetLastBuildSeconds();
}
