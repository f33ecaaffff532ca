#include "PsiReferenceRaycaster.h"

#include "PsiIntegration.h"
#include "PsiReferenceRays.h"
#include "PsiVec3.h"

#include <algorithm>
#include <cmath>

namespace psi
{
namespace
{

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
  auto scalarAt = [&](double tt)
  {
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
  const std::array<double, 16> worldToNdc = InverseMatrix(cam.NdcToWorld);
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
    const Segment seg = TransferSegment(sc, sa, sb, ts[k + 1] - ts[k]);
    acc = Over(acc, IntegrateWithPsi(seg, Psi(seg.taub * seg.D, seg.tauf * seg.D)));
  }
}

// Pixel (i, j)'s color: its pieces (sorted here) and surface layers composited front to back up
// to the opaque geometry, over that geometry's color or the background.
Vec3 CompositePixel(const ReferenceScene& sc, const ReferenceCamera& cam,
  const std::vector<double>& bps, int i, int j, std::vector<ReferencePiece>& list)
{
  std::sort(list.begin(), list.end(),
    [](const ReferencePiece& a, const ReferencePiece& b) { return a.t0 < b.t0; });
  const PixelRay ray = RayOf(cam, i, j);
  const double tOpaque = OpaqueDistance(cam, ray, i, j);
  Rgba acc{ { 0, 0, 0, 0 } };
  const std::vector<Layer> layers =
    SurfaceLayers(sc.Surfaces, ray.o, ray.d, std::min(ray.len, tOpaque));
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
  return OverBehind(cam, i, j, acc);
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
