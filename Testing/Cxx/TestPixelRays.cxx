// psi::PixelRaysOf against direct unprojection: for VTK's cameras (perspective and parallel,
// off-axis window centers, view shear, non-square viewports), every pixel's ray passes through
// the pixel's points on the near and far planes, points from near to far, and has t equal to
// the view depth where VTK's frusta make that possible.
#include "PsiPixelRays.h"
#include "PsiTestCheck.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
struct CameraCase
{
  const char* Name;
  bool Parallel;
  double WindowCenter[2];
  double Shear[3]; // dxdz, dydz, center
  int Width, Height;
};

// The clip -> view matrix of `k`, row-major (as PsiFrameCamera::FromRenderer builds it).
void InverseProjection(const CameraCase& k, double dcvc[16])
{
  vtkNew<vtkCamera> cam;
  cam->SetPosition(0.3, -0.2, 9.0);
  cam->SetFocalPoint(0.1, 0.2, 0.0);
  cam->SetViewUp(0.1, 1.0, 0.0);
  cam->SetClippingRange(0.5, 30.0);
  cam->SetViewAngle(35.0);
  cam->SetParallelScale(3.0);
  cam->SetParallelProjection(k.Parallel);
  cam->SetWindowCenter(k.WindowCenter[0], k.WindowCenter[1]);
  cam->SetViewShear(k.Shear[0], k.Shear[1], k.Shear[2]);
  vtkMatrix4x4* vcdc =
    cam->GetProjectionTransformMatrix(static_cast<double>(k.Width) / k.Height, -1, 1);
  vtkMatrix4x4::Invert(vcdc->GetData(), dcvc);
}

// The view-space point of window position (x, y) at device depth z.
void Unproject(
  const double dcvc[16], const CameraCase& k, double x, double y, double z, double p[3])
{
  const double ndc[4] = { 2 * x / k.Width - 1, 2 * y / k.Height - 1, z, 1 };
  double h[4];
  for (int r = 0; r < 4; ++r)
  {
    h[r] = 0;
    for (int c = 0; c < 4; ++c)
    {
      h[r] += dcvc[4 * r + c] * ndc[c];
    }
  }
  for (int r = 0; r < 3; ++r)
  {
    p[r] = h[r] / h[3];
  }
}

// Distance from p to the line o + t s, relative to |p - o|, and the t of p's foot.
double OffLine(const double o[3], const double s[3], const double p[3], double& t)
{
  const double d[3] = { p[0] - o[0], p[1] - o[1], p[2] - o[2] };
  const double x[3] = { d[1] * s[2] - d[2] * s[1], d[2] * s[0] - d[0] * s[2],
    d[0] * s[1] - d[1] * s[0] };
  const double ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  t = (d[0] * s[0] + d[1] * s[1] + d[2] * s[2]) / ss;
  return std::sqrt((x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / ss) / std::max(1e-12, std::sqrt(dd));
}

void TestCamera(const CameraCase& k)
{
  double dcvc[16];
  InverseProjection(k, dcvc);
  const psi::PixelRays rays = psi::PixelRaysOf(dcvc, k.Parallel, k.Width, k.Height);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(0, k.Width), uy(0, k.Height);
  double worstOff = 0, worstDepth = 0, worstDirection = 1e300;
  for (int i = 0; i < 200; ++i)
  {
    const double x = ux(rng), y = uy(rng);
    double o[3], s[3], pn[3], pf[3], tn, tf;
    rays.At(x, y, o, s);
    Unproject(dcvc, k, x, y, -1, pn);
    Unproject(dcvc, k, x, y, 1, pf);
    worstOff = std::max({ worstOff, OffLine(o, s, pn, tn), OffLine(o, s, pf, tf) });
    worstDirection = std::min(worstDirection, tf - tn);
    // With VTK's frusta (no shear), t is the view depth.
    if (k.Shear[0] == 0 && k.Shear[1] == 0)
    {
      worstDepth =
        std::max({ worstDepth, std::abs(tn + pn[2]) / -pn[2], std::abs(tf + pf[2]) / -pf[2] });
    }
    if (!k.Parallel && k.Shear[0] == 0 && k.Shear[1] == 0)
    {
      PSI_CHECK(
        o[0] == 0 && o[1] == 0 && o[2] == 0, "%s: perspective rays start at the eye", k.Name);
    }
  }
  if (k.Parallel)
  {
    PSI_CHECK(
      rays.Step[1][0] == 0 && rays.Step[2][2] == 0, "%s: parallel rays share one step", k.Name);
  }
  else
  {
    PSI_CHECK(rays.Origin[1][0] == 0 && rays.Origin[2][2] == 0,
      "%s: perspective rays share one origin", k.Name);
  }
  std::printf("%-28s off the ray %.2e  depth error %.2e  far - near t %.3g\n", k.Name, worstOff,
    worstDepth, worstDirection);
  PSI_CHECK(worstOff < 1e-9, "%s: near/far points off the pixel's ray by %g", k.Name, worstOff);
  PSI_CHECK(worstDepth < 1e-9, "%s: t differs from the view depth by %g", k.Name, worstDepth);
  PSI_CHECK(worstDirection > 0, "%s: the ray points from far to near", k.Name);
}
} // namespace

int main()
{
  const CameraCase cases[] = {
    { "perspective", false, { 0, 0 }, { 0, 0, 1 }, 512, 512 },
    { "perspective_wide", false, { 0, 0 }, { 0, 0, 1 }, 640, 360 },
    { "perspective_off_axis", false, { 0.4, -0.3 }, { 0, 0, 1 }, 300, 500 },
    { "perspective_sheared", false, { 0, 0 }, { 0.2, -0.1, 1 }, 512, 384 },
    { "parallel", true, { 0, 0 }, { 0, 0, 1 }, 512, 512 },
    { "parallel_off_axis", true, { -0.5, 0.2 }, { 0, 0, 1 }, 400, 256 },
    { "parallel_oblique", true, { 0, 0 }, { 0.3, 0.2, 1 }, 512, 384 },
  };
  for (const CameraCase& k : cases)
  {
    TestCamera(k);
  }
  return psitest::Report("TestPixelRays");
}
