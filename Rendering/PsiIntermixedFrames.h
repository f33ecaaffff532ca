// PsiIntermixedFrames: which volumes of a renderer are drawn intermixed, and which call of a
// frame draws them. Every visible volume of a renderer whose mapper is a vtkPsiVolumeMapper
// with cells to draw, and not drawn by a stand-in (vtkPsiVolumeMapper::SetDrawnByStandIn), is a
// member; with two or more, the first member's mapper that VTK calls in
// a frame (in each depth-peeling stage of it) draws all of them as one mesh, and the other
// members' calls of that frame draw nothing. The first call, not the first member: VTK's culler
// skips a volume outside the view, and then another member draws them all. The volume levels of
// detail of an interactive frame claim their frames apart from the full frames (Draws).
#ifndef PsiIntermixedFrames_h
#define PsiIntermixedFrames_h

#include <vector>

class vtkPsiVolumeMapper;
class vtkRenderer;
class vtkVolume;

struct PsiIntermixedMember
{
  vtkVolume* Volume = nullptr;
  vtkPsiVolumeMapper* Mapper = nullptr;
};

namespace PsiIntermixedFrames
{
/// What a claim draws: the full frames of the intermixed volumes, or the volume levels of detail
/// drawn together (Representations/PsiLODFrames.h). Each has its own claimant in a frame.
enum class Draws
{
  FullFrames,
  LevelsOfDetail
};

/// The visible volumes of `ren`, in the renderer's order (empty without a renderer).
std::vector<vtkVolume*> VisibleVolumes(vtkRenderer* ren);
/// The members of `ren`, in the renderer's order of its volumes.
std::vector<PsiIntermixedMember> Members(vtkRenderer* ren);
/// Whether this call of `mapper` draws the frame's intermixed volumes: true for the first
/// mapper called since `ren` started its frame (vtkCommand::StartEvent), and for each of its
/// later calls in the frame (depth-peeling stages); false for the other mappers' calls.
bool Claim(vtkRenderer* ren, const void* mapper, Draws what = Draws::FullFrames);
/// The mapper that claimed `ren`'s current frame's full frames (nullptr before any).
const vtkPsiVolumeMapper* Claimant(vtkRenderer* ren);
} // namespace PsiIntermixedFrames

#endif
