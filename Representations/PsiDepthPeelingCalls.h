// PsiDepthPeelingCalls: when a view has translucent geometry and depth peeling for volumes
// (ParaView's DepthPeelingForVolumes, on by default), VTK's vtkDualDepthPeelingPass renders each
// volume once per stage of every frame (the depth initialization, each peel, a final alpha
// blend), into its own draw buffers, and expects each call to integrate only that stage's depth
// intervals. 'Psi Volume' draws its whole image once, in the frame's first call, where the
// pass's draw buffer 0 accumulates what lies behind all translucent layers; it draws nothing in
// the later calls. Drawn in every call, the image was blended in several times through the
// pass's GL_MAX and front/back formulas: a stipple of stray pixels, also where no translucent
// surface covers the volume. A translucent surface behind or inside the volume is then still
// drawn over it (README, Known limitations).
#ifndef PsiDepthPeelingCalls_h
#define PsiDepthPeelingCalls_h

#include "vtkType.h"

class vtkVolume;

class PsiDepthPeelingCalls
{
public:
  /// Whether to draw in this call: always outside the dual depth peeling pass; inside it, only
  /// in the frame's first call. The pass adds itself to the volume's property keys before its
  /// stages (vtkOpenGLRenderPass::PreRender) and removes itself after, so the keys' modification
  /// time is new in each frame's first call and the same in the later ones.
  bool DrawThisCall(vtkVolume* vol);
  /// Whether the last call came from the dual depth peeling pass.
  bool InPeelingPass() const { return this->Peeling; }

private:
  vtkMTimeType FrameKeysTime = 0;
  bool Peeling = false;
};

#endif
