#include "PsiReferenceMedia.h"

#include "PsiReferenceIntegrals.h"
#include "PsiReferenceRays.h"

#include <algorithm>

namespace psi
{
namespace
{
// One medium's pieces on a pixel's ray (sorted by entry) and the next one that may cover the
// stretch being integrated.
struct MediumRay
{
  const ReferenceScene* Scene;
  std::vector<ReferencePiece> Pieces;
  size_t Next = 0;
};

// Where the ray is cut: every piece's ends and breakpoint crossings up to `tEnd`, every layer.
std::vector<double> Cuts(const std::vector<MediumRay>& rays,
  const std::vector<std::vector<double>>& bps, const std::vector<Layer>& layers, double tEnd)
{
  std::vector<double> ts;
  for (size_t m = 0; m < rays.size(); ++m)
  {
    for (const ReferencePiece& p : rays[m].Pieces)
    {
      ts.push_back(p.t0);
      ts.push_back(p.t1);
      const double smin = std::min(p.s0, p.s1), smax = std::max(p.s0, p.s1);
      for (auto it = std::upper_bound(bps[m].begin(), bps[m].end(), smin);
           it != bps[m].end() && *it < smax; ++it)
      {
        ts.push_back(p.t0 + (p.t1 - p.t0) * (*it - p.s0) / (p.s1 - p.s0));
      }
    }
  }
  for (const Layer& layer : layers)
  {
    ts.push_back(layer.T);
  }
  for (double& t : ts)
  {
    t = std::min(std::max(t, 0.0), tEnd);
  }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

// The segment [a, b] of medium `r` (D = b - a), when one of its pieces covers the stretch.
bool MediumSegment(MediumRay& r, double a, double b, Segment& seg)
{
  const double mid = 0.5 * (a + b);
  while (r.Next < r.Pieces.size() && r.Pieces[r.Next].t1 <= mid)
  {
    ++r.Next;
  }
  if (r.Next == r.Pieces.size() || r.Pieces[r.Next].t0 > mid)
  {
    return false;
  }
  const ReferencePiece& p = r.Pieces[r.Next];
  auto scalarAt = [&p](double t) { return p.s0 + (p.s1 - p.s0) * (t - p.t0) / (p.t1 - p.t0); };
  seg = TransferSegment(*r.Scene, scalarAt(a), scalarAt(b), b - a);
  return true;
}

// Pixel (i, j)'s color: the media's stretches and the surface layers composited front to back up
// to the opaque geometry, over that geometry's color or the background.
Vec3 CompositeMedia(std::vector<MediumRay>& rays, const std::vector<std::vector<double>>& bps,
  const std::vector<ReferenceSurface>& surfaces, const ReferenceCamera& cam, int i, int j)
{
  const PixelRay ray = RayOf(cam, i, j);
  const double tEnd = std::min(ray.len, OpaqueDistance(cam, ray, i, j));
  const std::vector<Layer> layers = SurfaceLayers(surfaces, ray.o, ray.d, tEnd);
  const std::vector<double> ts = Cuts(rays, bps, layers, tEnd);
  Rgba acc{ { 0, 0, 0, 0 } };
  size_t nextLayer = 0;
  std::vector<Segment> overlap;
  for (size_t k = 0; k + 1 < ts.size() && acc[3] <= 1 - 1e-12; ++k)
  {
    for (; nextLayer < layers.size() && layers[nextLayer].T <= ts[k]; ++nextLayer)
    {
      acc = Over(acc, layers[nextLayer].Color);
    }
    overlap.clear();
    for (MediumRay& r : rays)
    {
      Segment seg;
      if (MediumSegment(r, ts[k], ts[k + 1], seg))
      {
        overlap.push_back(seg);
      }
    }
    if (overlap.size() == 1)
    {
      const Segment& s = overlap[0];
      acc = Over(acc, IntegrateWithPsi(s, Psi(s.taub * s.D, s.tauf * s.D)));
    }
    else if (overlap.size() > 1)
    {
      acc = Over(acc, IntegrateReferenceMedia(overlap));
    }
  }
  for (; nextLayer < layers.size() && layers[nextLayer].T <= tEnd; ++nextLayer)
  {
    acc = Over(acc, layers[nextLayer].Color);
  }
  return OverBehind(cam, i, j, acc);
}
} // namespace

std::vector<double> RenderReferenceMedia(
  const std::vector<const ReferenceScene*>& media, const ReferenceCamera& cam)
{
  const int W = cam.Width, H = cam.Height;
  std::vector<std::vector<std::vector<ReferencePiece>>> pieces;
  std::vector<std::vector<double>> bps;
  std::vector<ReferenceSurface> surfaces;
  for (const ReferenceScene* sc : media)
  {
    pieces.push_back(ReferencePixelPieces(*sc, cam));
    bps.push_back(sc->Breakpoints);
    std::sort(bps.back().begin(), bps.back().end());
    surfaces.insert(surfaces.end(), sc->Surfaces.begin(), sc->Surfaces.end());
  }
  std::vector<double> image(3 * static_cast<size_t>(W) * H);
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const size_t px = static_cast<size_t>(j) * W + i;
      std::vector<MediumRay> rays;
      for (size_t m = 0; m < media.size(); ++m)
      {
        rays.push_back({ media[m], std::move(pieces[m][px]) });
        std::sort(rays.back().Pieces.begin(), rays.back().Pieces.end(),
          [](const ReferencePiece& a, const ReferencePiece& b) { return a.t0 < b.t0; });
      }
      const Vec3 rgb = CompositeMedia(rays, bps, surfaces, cam, i, j);
      std::copy(rgb.begin(), rgb.end(), image.begin() + 3 * px);
    }
  }
  return image;
}

} // namespace psi
