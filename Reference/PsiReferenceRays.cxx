#include "PsiReferenceRays.h"

#include <algorithm>
#include <cmath>

namespace psi
{

Vec3 TransformPoint(const std::array<double, 16>& m, double x, double y, double z)
{
  double o[4];
  for (int r = 0; r < 4; ++r)
  {
    o[r] = m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
  }
  return { { o[0] / o[3], o[1] / o[3], o[2] / o[3] } };
}

std::array<double, 16> InverseMatrix(const std::array<double, 16>& m)
{
  double a[4][8];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      a[r][c] = m[4 * r + c];
      a[r][c + 4] = r == c;
    }
  }
  for (int c = 0; c < 4; ++c)
  {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
    {
      if (std::abs(a[r][c]) > std::abs(a[p][c]))
      {
        p = r;
      }
    }
    std::swap(a[c], a[p]);
    const double d = a[c][c];
    for (double& v : a[c])
    {
      v /= d;
    }
    for (int r = 0; r < 4; ++r)
    {
      if (r != c)
      {
        const double f = a[r][c];
        for (int k = 0; k < 8; ++k)
        {
          a[r][k] -= f * a[c][k];
        }
      }
    }
  }
  std::array<double, 16> inverse{};
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      inverse[4 * r + c] = a[r][c + 4];
    }
  }
  return inverse;
}

PixelRay RayOf(const ReferenceCamera& cam, int i, int j)
{
  PixelRay ray;
  const double x = (i + 0.5) / cam.Width * 2 - 1, y = (j + 0.5) / cam.Height * 2 - 1;
  ray.o = TransformPoint(cam.NdcToWorld, x, y, -1);
  const Vec3 f = TransformPoint(cam.NdcToWorld, x, y, 1);
  ray.d = Sub(f, ray.o);
  ray.len = std::sqrt(Dot(ray.d, ray.d));
  ray.d = { { ray.d[0] / ray.len, ray.d[1] / ray.len, ray.d[2] / ray.len } };
  return ray;
}

double OpaqueDistance(const ReferenceCamera& cam, const PixelRay& ray, int i, int j)
{
  const size_t px = static_cast<size_t>(j) * cam.Width + i;
  if (cam.OpaqueDepth.empty() || !(cam.OpaqueDepth[px] < 1.0f))
  {
    return 1e300;
  }
  const double x = (i + 0.5) / cam.Width * 2 - 1, y = (j + 0.5) / cam.Height * 2 - 1;
  const Vec3 q = TransformPoint(cam.NdcToWorld, x, y, 2.0 * cam.OpaqueDepth[px] - 1.0);
  return std::sqrt(Dot(Sub(q, ray.o), Sub(q, ray.o)));
}

std::vector<Layer> SurfaceLayers(
  const std::vector<ReferenceSurface>& surfaces, const Vec3& o, const Vec3& d, double tMax)
{
  std::vector<Layer> layers;
  for (const ReferenceSurface& surface : surfaces)
  {
    const Rgba c{ { surface.Opacity * surface.Color[0], surface.Opacity * surface.Color[1],
      surface.Opacity * surface.Color[2], surface.Opacity } };
    for (const auto& tri : surface.Triangles)
    {
      const Vec3 e1 = Sub(tri[1], tri[0]), e2 = Sub(tri[2], tri[0]);
      const Vec3 p = Cross(d, e2);
      const double det = Dot(e1, p);
      if (std::abs(det) < 1e-300)
      {
        continue;
      }
      const Vec3 s = Sub(o, tri[0]);
      const double u = Dot(s, p) / det;
      const Vec3 q = Cross(s, e1);
      const double v = Dot(d, q) / det;
      const double t = Dot(e2, q) / det;
      if (u >= 0 && v >= 0 && u + v <= 1 && t > 0 && t < tMax)
      {
        layers.push_back({ t, c });
      }
    }
  }
  std::sort(layers.begin(), layers.end(), [](const Layer& a, const Layer& b) { return a.T < b.T; });
  return layers;
}

Segment TransferSegment(const ReferenceScene& sc, double sa, double sb, double D)
{
  double f[4], b[4];
  sc.Transfer(sa, f);
  sc.Transfer(sb, b);
  Segment seg;
  seg.Lf = { { f[0], f[1], f[2] } };
  seg.Lb = { { b[0], b[1], b[2] } };
  seg.tauf = f[3];
  seg.taub = b[3];
  seg.D = D;
  return seg;
}

Vec3 OverBehind(const ReferenceCamera& cam, int i, int j, const Rgba& acc)
{
  const size_t px = static_cast<size_t>(j) * cam.Width + i;
  Vec3 behind = cam.Background;
  if (!cam.OpaqueColor.empty() && !cam.OpaqueDepth.empty() && cam.OpaqueDepth[px] < 1.0f)
  {
    behind = { { cam.OpaqueColor[3 * px], cam.OpaqueColor[3 * px + 1],
      cam.OpaqueColor[3 * px + 2] } };
  }
  Vec3 rgb;
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = acc[k] + (1 - acc[3]) * behind[k];
  }
  return rgb;
}

} // namespace psi
