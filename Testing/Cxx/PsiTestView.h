// The view of the GL image tests: a window with one renderer and the volume, its cameras (outside
// the Wavelet meshes looking at their centre, or inside them), an opaque plane through them, the
// pixels read back, and the reference ray caster's camera of the same view.
#ifndef PsiTestView_h
#define PsiTestView_h

#include "PsiReferenceRaycaster.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <vector>

namespace psitest
{
/// The GL tests' view: a w x h window without multisampling, one renderer on the dark background
/// the references share, and (with a mapper) a volume drawn by `mapper` with `property`.
struct VolumeView
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;

  VolumeView(int w, int h, vtkAbstractVolumeMapper* mapper, vtkVolumeProperty* property)
  {
    this->Window->SetSize(w, h);
    this->Window->SetMultiSamples(0);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->AddRenderer(this->Renderer);
    if (mapper)
    {
      this->Volume->SetMapper(mapper);
      this->Volume->SetProperty(property);
      this->Renderer->AddVolume(this->Volume);
    }
  }
};

/// A perspective camera at (x, y, z) looking at the origin (the centre of the Wavelet meshes), y
/// up, view angle 30 degrees, the clipping range reset to what the renderer shows.
inline void LookAtCentre(vtkRenderer* ren, double x, double y, double z)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(0, 0, 0);
  cam->SetPosition(x, y, z);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(30);
  cam->SetParallelProjection(0);
  ren->ResetCameraClippingRange();
}

/// A perspective camera inside the Wavelet meshes, looking through them, near plane at 0.05.
inline void SetCameraInside(vtkCamera* cam)
{
  cam->SetParallelProjection(0);
  cam->SetPosition(1.3, 0.7, 2.1);
  cam->SetFocalPoint(4, -2, -6);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(60);
  cam->SetClippingRange(0.05, 100);
}

/// A slanted unlit opaque quad through the middle of the Wavelet meshes ([-half, half] in x, y),
/// flat green so that its color is exact in the reference.
inline vtkSmartPointer<vtkActor> MakeOpaquePlane(double half)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-half, -half, 0.5);
  plane->SetPoint1(half, -half, -1.5);
  plane->SetPoint2(-half, half, 0.5);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(0.2, 0.7, 0.3);
  return actor;
}

/// Renders `win` and reads its pixels back as RGB in [0, 1], row by row from the bottom.
inline std::vector<double> GrabRGB(vtkRenderWindow* win)
{
  const int W = win->GetSize()[0], H = win->GetSize()[1];
  win->Render();
  vtkNew<vtkUnsignedCharArray> px;
  win->GetPixelData(0, 0, W - 1, H - 1, 0, px);
  std::vector<double> rgb(3 * W * H);
  for (int i = 0; i < 3 * W * H; ++i)
  {
    rgb[i] = px->GetValue(i) / 255.0;
  }
  return rgb;
}

/// The reference ray caster's camera for `ren`'s active camera at w x h pixels, with its
/// background.
inline psi::ReferenceCamera ReferenceCameraOf(vtkRenderer* ren, int w, int h)
{
  psi::ReferenceCamera cam;
  cam.Width = w;
  cam.Height = h;
  vtkNew<vtkMatrix4x4> m;
  m->DeepCopy(ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1));
  m->Invert();
  std::copy(m->GetData(), m->GetData() + 16, cam.NdcToWorld.begin());
  const double* bg = ren->GetBackground();
  cam.Background = { { bg[0], bg[1], bg[2] } };
  return cam;
}
} // namespace psitest

#endif
