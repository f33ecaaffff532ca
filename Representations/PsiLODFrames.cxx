#include "PsiLODFrames.h"

#include "PsiIntermixedFrames.h"
#include "PsiLODVolume.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"
#include "vtkVolumeMapper.h"

#include <algorithm>
#include <array>

namespace
{
// Set while one call draws every display's level of detail: their mappers then draw as alone.
bool DrawingTogether = false;

// The visible displays of `ren` that draw their volume level of detail in this frame, in the
// renderer's order.
std::vector<PsiLODVolume*> Members(vtkRenderer* ren)
{
  std::vector<PsiLODVolume*> members;
  for (vtkVolume* vol : PsiIntermixedFrames::VisibleVolumes(ren))
  {
    auto* actor = PsiLODVolume::SafeDownCast(vol);
    if (actor && actor->DrawsVolumeLOD())
    {
      members.push_back(actor);
    }
  }
  return members;
}

// The world box that `actor`'s level of detail draws: its image's box, or the box its mapper is
// cropped to (in parallel, this process's piece of a lattice spanned over every volume shown),
// through the actor's matrix. False when there is none.
bool DrawnBox(PsiLODVolume* actor, double box[6])
{
  auto* mapper = vtkVolumeMapper::SafeDownCast(actor->GetLowLODVolumeMapper());
  const double* own = !mapper ? nullptr
    : mapper->GetCropping()   ? mapper->GetCroppingRegionPlanes()
                              : mapper->GetBounds();
  if (!own || own[0] > own[1])
  {
    return false;
  }
  vtkBoundingBox world;
  vtkMatrix4x4* matrix = actor->GetMatrix();
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[4] = { own[corner & 1], own[2 + ((corner >> 1) & 1)],
      own[4 + ((corner >> 2) & 1)], 1 };
    double q[4];
    matrix->MultiplyPoint(p, q);
    world.AddPoint(q[0] / q[3], q[1] / q[3], q[2] / q[3]);
  }
  world.GetBounds(box);
  return true;
}

// The eye's depth of a point: its distance from the eye along the view direction.
double Depth(vtkCamera* camera, const double p[3])
{
  double dop[3];
  camera->GetDirectionOfProjection(dop);
  const double* eye = camera->GetPosition();
  return (p[0] - eye[0]) * dop[0] + (p[1] - eye[1]) * dop[1] + (p[2] - eye[2]) * dop[2];
}

double CenterDepth(vtkCamera* camera, const double* b)
{
  const double c[3] = { (b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2 };
  return Depth(camera, c);
}

// Whether box `a` must be drawn before box `b` (is behind it): a plane between the two boxes
// across an axis, with the eye on b's side (perspective) or the view looking from b's side
// (parallel projection). A line crosses a plane once, so no ray from the eye meets b before a;
// where several axes separate them and disagree, no ray meets both. False without such a plane.
bool Behind(const double* a, const double* b, vtkCamera* camera)
{
  double dop[3];
  camera->GetDirectionOfProjection(dop);
  const double* eye = camera->GetPosition();
  const bool parallel = camera->GetParallelProjection() != 0;
  for (int k = 0; k < 3; ++k)
  {
    const bool aLow = a[2 * k + 1] <= b[2 * k];  // a below b along k
    const bool aHigh = b[2 * k + 1] <= a[2 * k]; // a above b along k
    if (!aLow && !aHigh)
    {
      continue;
    }
    const double plane = aLow ? (a[2 * k + 1] + b[2 * k]) / 2 : (b[2 * k + 1] + a[2 * k]) / 2;
    // the eye's side of the plane: above it, or (parallel) looking down along k
    const bool eyeHigh = parallel ? dop[k] < 0 : eye[k] > plane;
    return aLow == eyeHigh;
  }
  return false;
}
} // namespace

std::vector<int> PsiLODFrames::BackToFront(
  const std::vector<const double*>& boxes, vtkCamera* camera)
{
  std::vector<int> left, order;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
  {
    left.push_back(i);
  }
  while (!left.empty())
  {
    // the farthest box that no other box left must be drawn before (the farthest of all if
    // every box has one: boxes that overlap, in a cycle)
    int pick = -1, farthest = -1;
    for (int i : left)
    {
      bool free = true;
      for (int j : left)
      {
        free = free && (j == i || !Behind(boxes[j], boxes[i], camera));
      }
      const auto deeper = [&](int other)
      { return other < 0 || CenterDepth(camera, boxes[i]) > CenterDepth(camera, boxes[other]); };
      pick = free && deeper(pick) ? i : pick;
      farthest = deeper(farthest) ? i : farthest;
    }
    pick = pick >= 0 ? pick : farthest;
    order.push_back(pick);
    left.erase(std::find(left.begin(), left.end(), pick));
  }
  return order;
}

bool PsiLODFrames::DrawsAlone(vtkRenderer* ren, vtkAbstractVolumeMapper* mapper)
{
  if (DrawingTogether)
  {
    return true;
  }
  const std::vector<PsiLODVolume*> members = Members(ren);
  bool member = false;
  for (PsiLODVolume* m : members)
  {
    member = member || m->GetLowLODVolumeMapper() == mapper;
  }
  if (members.size() < 2 || !member)
  {
    return true;
  }
  if (!PsiIntermixedFrames::Claim(ren, mapper, PsiIntermixedFrames::Draws::LevelsOfDetail))
  {
    return false; // drawn by the frame's first call, with the others
  }
  std::vector<std::array<double, 6>> bounds(members.size(), { { 0, 0, 0, 0, 0, 0 } });
  std::vector<const double*> boxes;
  for (size_t i = 0; i < members.size(); ++i)
  {
    DrawnBox(members[i], bounds[i].data());
    boxes.push_back(bounds[i].data());
  }
  DrawingTogether = true;
  for (int i : BackToFront(boxes, ren->GetActiveCamera()))
  {
    members[i]->RenderVolumetricGeometry(ren);
  }
  DrawingTogether = false;
  return false;
}
