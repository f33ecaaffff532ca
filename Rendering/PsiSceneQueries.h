// PsiSceneQueries: what the renderer's other props put in the volume's way, asked of VTK's prop
// list once a frame (no GL). The frame plan reads them (near the volume, opaque geometry cuts
// cells: the shaders need the scene depth), the render target is told whether there is a depth
// to test against, and the depth-peeling calls whether translucent geometry goes unpeeled.
#ifndef PsiSceneQueries_h
#define PsiSceneQueries_h

class vtkRenderWindow;
class vtkRenderer;
class vtkVolume;

namespace psi
{
/// Whether a visible opaque prop other than `vol` overlaps the volume's bounds: only then can
/// opaque geometry cut through cells, which needs the scene depth in the fragment shader.
bool OpaqueGeometryOverlaps(vtkRenderer* ren, vtkVolume* vol);
/// Whether any visible prop other than volumes has opaque geometry (else the scene depth is the
/// cleared far plane everywhere, and the depth test would reject nothing).
bool SceneHasOpaqueGeometry(vtkRenderer* ren);
/// Whether any visible prop other than volumes has translucent geometry.
bool SceneHasTranslucentGeometry(vtkRenderer* ren);
/// Whether `win` draws an interactive frame (the camera moving): ParaView's render view asks for
/// 5 frames per second during interactive renders (vtkPVRenderView::InteractiveRender) and for
/// 0.002 during still ones (StillRender, which screenshots use), in 5.11, 5.13 and 6.1 alike.
bool IsInteractiveRender(vtkRenderWindow* win);
}

#endif
