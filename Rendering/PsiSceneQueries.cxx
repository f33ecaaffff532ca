#include "PsiSceneQueries.h"

#include "vtkRenderWindow.h"

#include "vtkMath.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

namespace
{
// Whether a visible prop other than volumes has opaque (else translucent) geometry, within `box`
// when given.
bool AnyProp(vtkRenderer* ren, const double* box, bool opaque = true)
{
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* p = props->GetNextProp(it))
  {
    if (!p->GetVisibility() || p->IsA("vtkVolume") ||
      !(opaque ? p->HasOpaqueGeometry() : p->HasTranslucentPolygonalGeometry()))
    {
      continue;
    }
    // An actor with no data (ParaView keeps one per hidden representation: bounds
    // uninitialized, VTK_DOUBLE_MAX or min > max) draws nothing.
    const double* b = p->GetBounds();
    if (!b || !vtkMath::AreBoundsInitialized(b))
    {
      continue;
    }
    if (!box ||
      (b[0] <= box[1] && box[0] <= b[1] && b[2] <= box[3] && box[2] <= b[3] && b[4] <= box[5] &&
        box[4] <= b[5]))
    {
      return true;
    }
  }
  return false;
}
} // namespace

bool psi::OpaqueGeometryOverlaps(vtkRenderer* ren, vtkVolume* vol)
{
  double vb[6];
  vol->GetBounds(vb);
  return AnyProp(ren, vb);
}

bool psi::SceneHasOpaqueGeometry(vtkRenderer* ren)
{
  return AnyProp(ren, nullptr);
}

bool psi::SceneHasTranslucentGeometry(vtkRenderer* ren)
{
  return AnyProp(ren, nullptr, false);
}

bool psi::IsInteractiveRender(vtkRenderWindow* win)
{
  return win && win->GetDesiredUpdateRate() > 1.0;
}
