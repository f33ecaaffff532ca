// The order in which the levels of detail of several displays are drawn
// (PsiLODFrames::BackToFront, GL-free): back to front by their world boxes.
//  - A long bar along the view direction beside a small box: the bar's near end covers the box,
//    so the box is drawn first, though the bar's center lies far deeper (the centers' order would
//    paste the box over the bar). Seen from the other side, the other order.
//  - The same under a parallel projection, tilted toward the box and away from it.
//  - Boxes that overlap: by the depth of their centers, the far first.
#include "PsiLODFrames.h"
#include "PsiTestCheck.h"

#include "vtkCamera.h"
#include "vtkNew.h"

#include <vector>

namespace
{
// A long bar along z (its near end at z = 2) and a small box beside it at x > 1.5.
const double Bar[6] = { -1, 1, -1, 1, 2, 100 };
const double Box[6] = { 1.5, 4, -1, 1, 6, 7 };

std::vector<int> Order(const double* a, const double* b, vtkCamera* camera)
{
  return PsiLODFrames::BackToFront({ a, b }, camera);
}

void CheckPerspective()
{
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0, 0, 0);
  camera->SetFocalPoint(0, 0, 10);
  camera->SetViewUp(0, 1, 0);
  // the ray from the eye to (1.5, 0, 6) crosses the bar at z in [2, 4]: the bar covers the box
  PSI_CHECK(Order(Bar, Box, camera) == std::vector<int>({ 1, 0 }) &&
      Order(Box, Bar, camera) == std::vector<int>({ 0, 1 }),
    "perspective: the box behind the bar's near end is drawn first, in either order of input");
  camera->SetPosition(10, 0, 0); // the eye beyond the box: the box covers the bar
  camera->SetFocalPoint(0, 0, 10);
  PSI_CHECK(Order(Bar, Box, camera) == std::vector<int>({ 0, 1 }),
    "perspective: seen from the box's side, the bar is drawn first");
}

void CheckParallel()
{
  vtkNew<vtkCamera> camera;
  camera->ParallelProjectionOn();
  camera->SetPosition(0, 0, 0);
  camera->SetFocalPoint(0.3, 0, 1); // rays toward +x: through the bar, then the box
  camera->SetViewUp(0, 1, 0);
  const std::vector<int> toward = Order(Bar, Box, camera);
  camera->SetFocalPoint(-0.3, 0, 1); // rays toward -x: through the box, then the bar
  const std::vector<int> away = Order(Bar, Box, camera);
  PSI_CHECK(toward == std::vector<int>({ 1, 0 }) && away == std::vector<int>({ 0, 1 }),
    "parallel projection: the box first when the rays go from the bar to it, else the bar");
}

void CheckOverlapping()
{
  const double a[6] = { 0, 2, 0, 2, 0, 2 };
  const double b[6] = { 1, 3, 1, 3, 1, 3 };
  vtkNew<vtkCamera> camera;
  camera->SetPosition(-10, 1, 1);
  camera->SetFocalPoint(0, 1, 1);
  camera->SetViewUp(0, 1, 0);
  PSI_CHECK(Order(a, b, camera) == std::vector<int>({ 1, 0 }) &&
      Order(b, a, camera) == std::vector<int>({ 0, 1 }),
    "overlapping boxes: the deeper center first");
}
} // namespace

int main()
{
  CheckPerspective();
  CheckParallel();
  CheckOverlapping();
  return psitest::Report("TestLODFrames");
}
