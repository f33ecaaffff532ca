// PsiLODFrames: the volume levels of detail of several 'Psi Volume' displays in one renderer,
// drawn together. VTK draws each volume on its own, in the renderer's order of its props, and
// each ray-cast image is blended over what is drawn: the display drawn later covered the other
// wherever they overlapped on screen, whatever their depth. Here, as the full frames are claimed
// (Rendering/PsiIntermixedFrames.h), the first level-of-detail call of an interactive frame draws
// every display's level of detail, back to front in a visibility order of the world boxes they
// draw (each image's box, or in parallel the box its piece is cropped to), and
// the other displays' calls of that frame draw nothing. For boxes that share no space the order
// is exact (a plane between two disjoint boxes puts the eye's side in front); boxes that
// overlap are drawn by the depth of their centers, the far first (docs/decisions.md "The level
// of detail of several volumes", with vtkMultiVolume measured against it).
#ifndef PsiLODFrames_h
#define PsiLODFrames_h

#include "PsiVolumeRepresentationsModule.h"

#include <vector>

class vtkAbstractVolumeMapper;
class vtkCamera;
class vtkRenderer;

namespace PsiLODFrames
{
/// Whether this call of `mapper` (a display's volume level of detail) draws its own image as
/// alone: with fewer than two visible displays drawing their volume level of detail in `ren`,
/// or within the draw of all of them. False when the call was handled: this frame's first call
/// drew every display's level of detail, or a later call of the frame draws nothing.
bool DrawsAlone(vtkRenderer* ren, vtkAbstractVolumeMapper* mapper);

/// A back-to-front order of world boxes (xmin, xmax, ymin, ymax, zmin, zmax) seen by `camera`:
/// the indices of `boxes`, the first drawn first.
PSIVOLUMEREPRESENTATIONS_EXPORT std::vector<int> BackToFront(
  const std::vector<const double*>& boxes, vtkCamera* camera);
} // namespace PsiLODFrames

#endif
