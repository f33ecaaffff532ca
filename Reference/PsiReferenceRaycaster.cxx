#include "PsiReferenceRaycaster.h"

#include "PsiIntegration.h"
#include "PsiVec3.h"

#include <algorithm>
#include <cmath>

namespace psi
{
namespace
{
// Homogeneous transform of (x, y, z, 1) by a row-major matrix, divided by w.
Vec3 Transform(const std::array<double, 16>& m, double x, double y, double z)
{
  double o[4];
  for (int r = 0; r < 4; ++r)
  {
    o[r] = m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
  }
  return { { o[0] / o[3], o[1] / o[3], o[2] / o[3] } };
}

struct TetGeometry
{
  Vec3 Normal[4]; // outward face normals, face i opposite vertex i
  Vec3 Anchor[4]; // a point of face i
  Vec3 Gradient;  // of the linear scalar
  Vec3 Origin;    // vertex 0
  double S0;
  bool Valid;
};

TetGeometry MakeTet(const ReferenceScene& sc, const std::array<int, 4>& t)
{
  TetGeometry g{};
  Vec3 V[4];
  for (int i = 0; i < 4; ++i)
  {
    V[i] = sc.Points[t[i]];
  }
  const Vec3 e1 = Sub(V[1], V[0]), e2 = Sub(V[2], V[0]), e3 = Sub(V[3], V[0]);
  const double det = Dot(e1, Cross(e2, e3));
  g.Valid = std::abs(det) > 0 && std::isfinite(det);
  if (!g.Valid)
  {
    return g;
  }
  for (int i = 0; i < 4; ++i)
  {
    const Vec3 &a = V[(i + 1) % 4], &b = V[(i + 2) % 4], &c = V[(i + 3) % 4];
    Vec3 n = Cross(Sub(b, a), Sub(c, a));
    if (Dot(n, Sub(V[i], a)) > 0)
    {
      n = { { -n[0], -n[1], -n[2] } };
    }
    g.Normal[i] = n;
    g.Anchor[i] = a;
  }
  // Gradient: solve [e1 e2 e3]^T g = ds by Cramer's rule.
  const double ds[3] = { sc.Scalars[t[1]] - sc.Scalars[t[0]], sc.Scalars[t[2]] - sc.Scalars[t[0]],
    sc.Scalars[t[3]] - sc.Scalars[t[0]] };
  const Vec3 c23 = Cross(e2, e3), c31 = Cross(e3, e1), c12 = Cross(e1, e2);
  for (int k = 0; k < 3; ++k)
  {
    g.Gradient[k] = (ds[0] * c23[k] + ds[1] * c31[k] + ds[2] * c12[k]) / det;
  }
  g.Origin = V[0];
  g.S0 = sc.Scalars[t[0]];
  return g;
}
} // namespace

namespace
{
struct Layer
{
  double T;
  Rgba Color; // premultiplied
};

// The crossings of the ray o + t d (0 < t < tMax) with the surfaces' triangles, nearest first
// (Moeller and Trumbore's ray/triangle test).
std::vector<Layer> SurfaceLayers(
  const ReferenceScene& sc, const Vec3& o, const Vec3& d, double tMax)
{
  std::vector<Layer> layers;
  for (const ReferenceSurface& surface : sc.Surfaces)
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
// The inverse of a row-major 4x4 matrix (Gauss-Jordan, partial pivoting).
std::array<double, 16> Inverse(const std::array<double, 16>& m)
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

// The ray of pixel (i, j): from the near plane `o` along the unit direction `d`, `len` to the
// far plane.
struct PixelRay
{
  Vec3 o, d;
  double len;
};

PixelRay RayOf(const ReferenceCamera& cam, int i, int j)
{
  PixelRay ray;
  const double x = (i + 0.5) / cam.Width * 2 - 1, y = (j + 0.5) / cam.Height * 2 - 1;
  ray.o = Transform(cam.NdcToWorld, x, y, -1);
  const Vec3 f = Transform(cam.NdcToWorld, x, y, 1);
  ray.d = Sub(f, ray.o);
  ray.len = std::sqrt(Dot(ray.d, ray.d));
  ray.d = { { ray.d[0] / ray.len, ray.d[1] / ray.len, ray.d[2] / ray.len } };
  return ray;
}

// The pixels (i0..i1, j0..j1) tetrahedron `t` may cover: its screen box; every pixel when it
// reaches behind the near plane.
std::array<int, 4> ScreenBox(const ReferenceScene& sc, const std::array<int, 4>& t,
  const std::array<double, 16>& worldToNdc, int W, int H)
{
  double lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 };
  for (int v = 0; v < 4; ++v)
  {
    const Vec3& p = sc.Points[t[v]];
    double c[4];
    for (int r = 0; r < 4; ++r)
    {
      c[r] = worldToNdc[4 * r] * p[0] + worldToNdc[4 * r + 1] * p[1] +
        worldToNdc[4 * r + 2] * p[2] + worldToNdc[4 * r + 3];
    }
    if (c[3] <= 0 || c[2] < -c[3])
    {
      return { { 0, W - 1, 0, H - 1 } };
    }
    for (int k = 0; k < 2; ++k)
    {
      lo[k] = std::min(lo[k], c[k] / c[3]);
      hi[k] = std::max(hi[k], c[k] / c[3]);
    }
  }
  return { { std::max(0, static_cast<int>(std::floor((lo[0] + 1) / 2 * W - 0.5))),
    std::min(W - 1, static_cast<int>(std::ceil((hi[0] + 1) / 2 * W - 0.5))),
    std::max(0, static_cast<int>(std::floor((lo[1] + 1) / 2 * H - 0.5))),
    std::min(H - 1, static_cast<int>(std::ceil((hi[1] + 1) / 2 * H - 0.5))) } };
}

// The piece of `ray` inside tetrahedron `g` (exact ray / face-plane clipping); false when the
// ray misses it.
bool Clip(const TetGeometry& g, const PixelRay& ray, ReferencePiece& piece)
{
  const Vec3& o = ray.o;
  const Vec3& d = ray.d;
  double tin = 0, tout = ray.len;
  bool hit = true;
  for (int f = 0; f < 4 && hit; ++f)
  {
    const double den = Dot(g.Normal[f], d);
    const double num = Dot(g.Normal[f], Sub(g.Anchor[f], o));
    if (den == 0)
    {
      hit = num >= 0;
      continue;
    }
    const double tf = num / den;
    if (den < 0)
    {
      tin = std::max(tin, tf);
    }
    else
    {
      tout = std::min(tout, tf);
    }
    hit = tout > tin;
  }
  if (!hit)
  {
    return false;
  }
  auto scalarAt = [&](double tt) {
    const Vec3 p = { { o[0] + tt * d[0], o[1] + tt * d[1], o[2] + tt * d[2] } };
    return g.S0 + Dot(g.Gradient, Sub(p, g.Origin));
  };
  piece = { tin, tout, scalarAt(tin), scalarAt(tout) };
  return true;
}

} // namespace

std::vector<std::vector<ReferencePiece>> ReferencePixelPieces(
  const ReferenceScene& sc, const ReferenceCamera& cam)
{
  const int W = cam.Width, H = cam.Height;
  std::vector<std::vector<ReferencePiece>> pixels(static_cast<size_t>(W) * H);
  // Screen boxes: tetrahedra are binned into the pixels they may cover.
  const std::array<double, 16> worldToNdc = Inverse(cam.NdcToWorld);
  for (const auto& t : sc.Tets)
  {
    const TetGeometry g = MakeTet(sc, t);
    if (!g.Valid)
    {
      continue;
    }
    const std::array<int, 4> box = ScreenBox(sc, t, worldToNdc, W, H);
    for (int j = box[2]; j <= box[3]; ++j)
    {
      for (int i = box[0]; i <= box[1]; ++i)
      {
        ReferencePiece piece;
        if (Clip(g, RayOf(cam, i, j), piece))
        {
          pixels[static_cast<size_t>(j) * W + i].push_back(piece);
        }
      }
    }
  }
  return pixels;
}

namespace
{
// Integrates piece `p` of a ray (ended at `t1`, scalar `s1` there) onto `acc`, split at the
// transfer function's breakpoints `bps` (sorted) and at the surface layers, which are composited
// at their depths.
void IntegratePiece(const ReferenceScene& sc, const std::vector<double>& bps,
  const ReferencePiece& p, double t1, double s1, const std::vector<Layer>& layers,
  size_t& nextLayer, Rgba& acc)
{
  // Split points along the segment: every breakpoint strictly between the end scalars.
  std::vector<double> ts = { p.t0 };
  const double smin = std::min(p.s0, s1), smax = std::max(p.s0, s1);
  for (auto it = std::upper_bound(bps.begin(), bps.end(), smin); it != bps.end() && *it < smax;
       ++it)
  {
    ts.push_back(p.t0 + (t1 - p.t0) * (*it - p.s0) / (s1 - p.s0));
  }
  for (const Layer& layer : layers)
  {
    if (layer.T > p.t0 && layer.T < t1)
    {
      ts.push_back(layer.T);
    }
  }
  ts.push_back(t1);
  std::sort(ts.begin(), ts.end());
  for (size_t k = 0; k + 1 < ts.size(); ++k)
  {
    for (; nextLayer < layers.size() && layers[nextLayer].T <= ts[k]; ++nextLayer)
    {
      acc = Over(acc, layers[nextLayer].Color);
    }
    const double sa = p.s0 + (s1 - p.s0) * (ts[k] - p.t0) / (t1 - p.t0);
    const double sb = p.s0 + (s1 - p.s0) * (ts[k + 1] - p.t0) / (t1 - p.t0);
    double f[4], b[4];
    sc.Transfer(sa, f);
    sc.Transfer(sb, b);
    Segment seg;
    seg.Lf = { { f[0], f[1], f[2] } };
    seg.Lb = { { b[0], b[1], b[2] } };
    seg.tauf = f[3];
    seg.taub = b[3];
    seg.D = ts[k + 1] - ts[k];
    const Rgba c = IntegrateWithPsi(seg, Psi(seg.taub * seg.D, seg.tauf * seg.D));
    acc = Over(acc, c);
  }
}

// Pixel (i, j)'s color: its pieces (sorted here) and surface layers composited front to back up
// to the opaque geometry, over that geometry's color or the background.
Vec3 CompositePixel(const ReferenceScene& sc, const ReferenceCamera& cam,
  const std::vector<double>& bps, int i, int j, std::vector<ReferencePiece>& list)
{
  const size_t px = static_cast<size_t>(j) * cam.Width + i;
  std::sort(list.begin(), list.end(),
    [](const ReferencePiece& a, const ReferencePiece& b) { return a.t0 < b.t0; });
  const PixelRay ray = RayOf(cam, i, j);
  double tOpaque = 1e300;
  if (!cam.OpaqueDepth.empty() && cam.OpaqueDepth[px] < 1.0f)
  {
    const double x = (i + 0.5) / cam.Width * 2 - 1, y = (j + 0.5) / cam.Height * 2 - 1;
    const Vec3 q = Transform(cam.NdcToWorld, x, y, 2.0 * cam.OpaqueDepth[px] - 1.0);
    tOpaque = std::sqrt(Dot(Sub(q, ray.o), Sub(q, ray.o)));
  }
  Rgba acc{ { 0, 0, 0, 0 } };
  const std::vector<Layer> layers = SurfaceLayers(sc, ray.o, ray.d, std::min(ray.len, tOpaque));
  size_t nextLayer = 0;
  for (const ReferencePiece& p : list)
  {
    if (p.t0 >= tOpaque || acc[3] > 1 - 1e-12)
    {
      break;
    }
    const double t1 = std::min(p.t1, tOpaque);
    const double s1 = p.s0 + (p.s1 - p.s0) * (t1 - p.t0) / (p.t1 - p.t0);
    IntegratePiece(sc, bps, p, t1, s1, layers, nextLayer, acc);
  }
  for (; nextLayer < layers.size() && layers[nextLayer].T <= tOpaque; ++nextLayer)
  {
    acc = Over(acc, layers[nextLayer].Color);
  }
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
} // namespace

std::vector<double> RenderReference(const ReferenceScene& sc, const ReferenceCamera& cam)
{
  const int W = cam.Width, H = cam.Height;
  std::vector<std::vector<ReferencePiece>> pixels = ReferencePixelPieces(sc, cam);
  std::vector<double> image(3 * static_cast<size_t>(W) * H);
  std::vector<double> bps = sc.Breakpoints;
  std::sort(bps.begin(), bps.end());
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const size_t px = static_cast<size_t>(j) * W + i;
      const Vec3 rgb = CompositePixel(sc, cam, bps, i, j, pixels[px]);
      for (int k = 0; k < 3; ++k)
      {
        image[3 * px + k] = rgb[k];
      }
    }
  }
  return image;
}

} // namespace psi
