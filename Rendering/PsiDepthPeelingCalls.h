// PsiDepthPeelingCalls: when a view has translucent geometry and depth peeling for volumes
// (ParaView's DepthPeelingForVolumes, on by default), VTK's vtkDualDepthPeelingPass renders each
// volume once per stage of every frame, into its own draw buffers, and expects each call to
// integrate only the volume between the depths its textures give per pixel:
//  - before the peels: in front of all translucent layers, and behind them up to opaque geometry;
//  - each peel: between the front layer just peeled and the next, and between the next back
//    layer and the back layer just peeled;
//  - the final alpha blend: between the layers left unpeeled.
// This class finds the stage of a call, from the shader replacements the pass makes for it (its
// public PreReplaceShaderValues), and hands the pass's texture uniforms to a program (its
// SetShaderParameters). The mapper then clips its ray segments to the stage's intervals
// (Shaders/PsiDepthPeelFS.glsl) and the composite writes the pass's outputs
// (Shaders/PsiCompositeFS.glsl).
#ifndef PsiDepthPeelingCalls_h
#define PsiDepthPeelingCalls_h

#include "vtkNew.h"
#include "vtkType.h"

class vtkAbstractMapper;
class vtkDualDepthPeelingPass;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkVolume;
class vtkWindow;

class PsiDepthPeelingCalls
{
public:
  PsiDepthPeelingCalls();
  ~PsiDepthPeelingCalls();
  /// What a call draws (peelStage in the shaders).
  enum Stage
  {
    Skip = -1,         ///< nothing: a later call of a pass whose stages were not recognized
    Plain = 0,         ///< the whole volume: not within depth peeling
    OutsideLayers = 1, ///< before the peels: in front of and behind all translucent layers
    Peel = 2,          ///< one peel's front and back intervals
    AlphaBlend = 3     ///< the final blend of what lies between unpeeled layers
  };

  /// The stage of this call of `mapper` for `vol`. A pass whose stages are not recognized gets
  /// the whole volume once a frame, in its first call (behind all translucent layers): the pass
  /// adds itself to the volume's property keys before its stages (vtkOpenGLRenderPass::PreRender)
  /// and removes itself after, so the keys' modification time is new in each frame's first call.
  Stage StageOf(vtkAbstractMapper* mapper, vtkVolume* vol);
  /// The stage of the last call (StageOf).
  Stage GetStage() const { return this->LastStage; }
  /// Sets the pass's texture uniforms (outerDepthTex, innerDepthTex, lastFrontColorTex,
  /// opaqueDepthTex, depthRangeTex, as the stage has them) on the bound `program`. Those the
  /// stage does not have name a 1 x 1 placeholder texture: samplers of different types may not
  /// share a texture unit, and unset ones all name unit 0. Deactivate() after the draws.
  void SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkVolume* vol,
    vtkOpenGLRenderWindow* renWin);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* win);
  /// Outside dual depth peeling for volumes VTK draws translucent geometry before all volumes: a
  /// surface in front of or inside the volume cannot be intermixed. Warns (from `mapper`) once
  /// while the last call was not peeled and the view has translucent geometry.
  void NoteTranslucentGeometry(vtkAbstractMapper* mapper, vtkRenderer* ren);
  /// Images a stage draws: the back interval's and, before the peels and in each peel, the front
  /// interval's.
  static int ImagesOf(Stage s) { return s == OutsideLayers || s == Peel ? 2 : 1; }

private:
  vtkDualDepthPeelingPass* Pass = nullptr; // of the current call; owned by the renderer
  vtkMTimeType FrameKeysTime = 0;
  Stage LastStage = Plain;
  bool NotedTranslucent = false;
  vtkNew<vtkTextureObject> Placeholder;
};

#endif
