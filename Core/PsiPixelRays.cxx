#include "PsiPixelRays.h"

#include <cmath>

namespace psi
{
namespace
{
// Column c of the row-major 4x4 matrix m.
void Column(const double m[16], int c, double out[4])
{
  for (int r = 0; r < 4; ++r)
  {
    out[r] = m[4 * r + c];
  }
}
} // namespace

void PixelRays::At(double x, double y, double origin[3], double step[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    origin[k] = this->Origin[0][k] + x * this->Origin[1][k] + y * this->Origin[2][k];
    step[k] = this->Step[0][k] + x * this->Step[1][k] + y * this->Step[2][k];
  }
}

PixelRays PixelRaysOf(const double dcvc[16], bool parallel, int width, int height)
{
  // h(x, y, z) = hx x + hy y + h0 + z c2, from ndc = (2x/W - 1, 2y/H - 1, z, 1). Every pixel's
  // line {h(x, y, z)} passes through the homogeneous point c2 (z -> infinity): the eye in
  // perspective, the common direction of the rays (c2.w = 0) in parallel projection.
  double c0[4], c1[4], c2[4], c3[4];
  Column(dcvc, 0, c0);
  Column(dcvc, 1, c1);
  Column(dcvc, 2, c2);
  Column(dcvc, 3, c3);
  double lin[3][4]; // h on the near plane (z = -1): lin[0] + x lin[1] + y lin[2]
  for (int r = 0; r < 4; ++r)
  {
    lin[0][r] = c3[r] - c0[r] - c1[r] - c2[r];
    lin[1][r] = 2.0 * c0[r] / width;
    lin[2][r] = 2.0 * c1[r] / height;
  }
  // At the viewport's center, where the constant scales are taken.
  double hc[4];
  for (int r = 0; r < 4; ++r)
  {
    hc[r] = lin[0][r] + 0.5 * width * lin[1][r] + 0.5 * height * lin[2][r];
  }
  PixelRays rays;
  if (!parallel)
  {
    // O = the eye; S = h.xyz - h.w eye, the direction from the eye to the pixel's near point
    // (times h.w, one sign over the viewport), linear in h and so affine in (x, y).
    double eye[3];
    for (int k = 0; k < 3; ++k)
    {
      eye[k] = c2[k] / c2[3];
    }
    double sc[3];
    for (int k = 0; k < 3; ++k)
    {
      for (int j = 0; j < 3; ++j)
      {
        rays.Step[j][k] = lin[j][k] - lin[j][3] * eye[k];
      }
      rays.Origin[0][k] = eye[k];
      sc[k] = hc[k] - hc[3] * eye[k];
    }
    // Away from the eye, |S.z| = 1 at the center (everywhere for VTK's frusta).
    const double c = (hc[3] > 0 ? 1.0 : -1.0) / std::abs(sc[2]);
    for (auto& row : rays.Step)
    {
      for (double& v : row)
      {
        v *= c;
      }
    }
    return rays;
  }
  // Parallel: h.w is the same at every pixel; the near point is affine in (x, y) and the rays
  // share the direction c2.xyz / h.w (near to far), scaled to |S.z| = 1.
  const double w = hc[3];
  double step[3];
  for (int k = 0; k < 3; ++k)
  {
    step[k] = c2[k] / w;
  }
  const double scale =
    step[2] != 0 ? 1.0 / std::abs(step[2]) : 1.0 / std::sqrt(step[0] * step[0] + step[1] * step[1]);
  for (int k = 0; k < 3; ++k)
  {
    rays.Step[0][k] = step[k] * scale;
  }
  // O: the ray's point on the view plane z = 0, so that t is the view depth.
  const double* S = rays.Step[0];
  for (int j = 0; j < 3; ++j)
  {
    double pn[3];
    for (int k = 0; k < 3; ++k)
    {
      pn[k] = lin[j][k] / w;
    }
    for (int k = 0; k < 3; ++k)
    {
      rays.Origin[j][k] = S[2] != 0 ? pn[k] - pn[2] / S[2] * S[k] : pn[k];
    }
  }
  return rays;
}

} // namespace psi
