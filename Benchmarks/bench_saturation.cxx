// Benchmark (not a test): how much of a projected-tetrahedra frame lies behind the point where its
// pixel is already opaque, the work that front-to-back compositing with early ray termination
// (Levoy 1990, "Efficient ray tracing of volume data", adaptive ray termination) could skip.
//
// A projected-tetrahedra renderer shades one fragment per tetrahedron and pixel whose center ray
// crosses it (Shirley & Tuchman 1990), so a pixel's fragments are its ray's segments through the
// tetrahedra. Each pixel's ray is walked front to back as the exact reference does
// (PsiReferenceRaycaster: the same rays from the near plane, the same ray / face-plane clipping,
// each segment split at the transfer function's breakpoints, tau linear on each piece), and the
// accumulated opacity after optical depth E along the ray is
//   alpha = 1 - exp(-E),   E = int tau dt   (Moreland & Angel 2004 Eq. 8 per piece),
// so alpha first reaches a threshold a where E reaches -ln(1 - a): inside the piece of the ray
// where that happens, at the root of the piece's quadratic exponent (psi::TruncationPoint).
// Behind that point t_a lie
//   - the fragments whose segment starts at or behind t_a (the one that crosses t_a must still be
//     shaded to know that the pixel is opaque), and
//   - the ray length behind t_a,
// each summed over all pixels and given as a share of all fragments and of all ray length inside
// the mesh.
//
// Usage: bench_saturation MESH.vtu SCENE.txt [--no-check]
//   MESH.vtu and SCENE.txt as psi_reference_render reads them (psivolume.accuracy.Capture writes
//   both; Benchmarks/bench_saturation.py does for the benchmarks' scenes). Prints "key value"
//   lines. Unless --no-check, the walk is compared with psi::RenderReference itself (Check below):
//   the largest differences are printed and a walk that is not the reference's exits 1.
#include "PsiIntegration.h"
#include "PsiReferenceRaycaster.h"
#include "PsiVec3.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
using psi::Vec3;

// The opacity thresholds a_k.
constexpr int NumThresholds = 2;
constexpr double Thresholds[NumThresholds] = { 0.99, 0.999 };

// ---- The scene (psi_reference_render's format) ------------------------------------------------

struct SceneFile
{
  std::string Array;
  std::string Association; // "points", "cells", or empty (then where the array is)
  int Component = -1;
  int Width = 256, Height = 256;
  double Unit = 1;
  std::array<double, 16> NdcToWorld{};
  std::vector<std::array<double, 5>> Table; // s, r, g, b, opacity
};

bool ReadScene(const char* path, SceneFile& s)
{
  std::ifstream in(path);
  std::string key;
  while (in >> key)
  {
    if (key == "array")
    {
      in >> std::quoted(s.Array);
    }
    else if (key == "association")
    {
      in >> s.Association;
    }
    else if (key == "component")
    {
      in >> s.Component;
    }
    else if (key == "size")
    {
      in >> s.Width >> s.Height;
    }
    else if (key == "background")
    {
      double ignored[3];
      in >> ignored[0] >> ignored[1] >> ignored[2];
    }
    else if (key == "unit")
    {
      in >> s.Unit;
    }
    else if (key == "ndc_to_world")
    {
      for (double& v : s.NdcToWorld)
      {
        in >> v;
      }
    }
    else if (key == "tf")
    {
      size_t n = 0;
      in >> n;
      s.Table.resize(n);
      for (auto& row : s.Table)
      {
        for (double& v : row)
        {
          in >> v;
        }
      }
    }
    else
    {
      std::cerr << "bench_saturation: unknown key '" << key << "' in " << path << "\n";
      return false;
    }
    if (in.fail())
    {
      std::cerr << "bench_saturation: bad value of '" << key << "' in " << path << "\n";
      return false;
    }
  }
  return !s.Array.empty() && !s.Table.empty() && s.Unit > 0 && s.Width > 0 && s.Height > 0;
}

double ScalarOf(vtkDataArray* a, vtkIdType i, int component)
{
  if (component >= 0 || a->GetNumberOfComponents() == 1)
  {
    return a->GetComponent(i, std::min(std::max(component, 0), a->GetNumberOfComponents() - 1));
  }
  double m = 0;
  for (int c = 0; c < a->GetNumberOfComponents(); ++c)
  {
    m += a->GetComponent(i, c) * a->GetComponent(i, c);
  }
  return std::sqrt(m);
}

// The grid's tetrahedra and scalars as psi_reference_render gathers them (cell scalars on
// private points).
bool GatherMesh(vtkUnstructuredGrid* grid, const SceneFile& s, psi::ReferenceScene& ref)
{
  vtkDataArray* pa =
    s.Association == "cells" ? nullptr : grid->GetPointData()->GetArray(s.Array.c_str());
  vtkDataArray* ca =
    pa || s.Association == "points" ? nullptr : grid->GetCellData()->GetArray(s.Array.c_str());
  if (!pa && !ca)
  {
    std::cerr << "bench_saturation: the mesh has no array \"" << s.Array << "\"\n";
    return false;
  }
  if (pa)
  {
    for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    {
      double p[3];
      grid->GetPoint(i, p);
      ref.Points.push_back({ { p[0], p[1], p[2] } });
      ref.Scalars.push_back(ScalarOf(pa, i, s.Component));
    }
  }
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const vtkIdType* pts;
    vtkIdType n;
    grid->GetCellPoints(c, n, pts);
    if (n != 4 || grid->GetCellType(c) != VTK_TETRA)
    {
      continue;
    }
    std::array<int, 4> tet;
    for (int v = 0; v < 4; ++v)
    {
      if (ca)
      {
        double p[3];
        grid->GetPoint(pts[v], p);
        tet[v] = static_cast<int>(ref.Points.size());
        ref.Points.push_back({ { p[0], p[1], p[2] } });
        ref.Scalars.push_back(ScalarOf(ca, c, s.Component));
      }
      else
      {
        tet[v] = static_cast<int>(pts[v]);
      }
    }
    ref.Tets.push_back(tet);
  }
  return true;
}

// ---- Attenuation: tau(s) = opacity(s) / unit, the table linear between rows, clamped ---------

struct Attenuation
{
  std::vector<double> S, Tau; // the table's rows; every S is a breakpoint

  explicit Attenuation(const SceneFile& s)
  {
    for (const auto& row : s.Table)
    {
      S.push_back(row[0]);
      Tau.push_back(row[4] / s.Unit);
    }
  }

  double operator()(double v) const
  {
    const auto it = std::lower_bound(S.begin(), S.end(), v);
    if (it == S.begin() || it == S.end())
    {
      return it == S.end() ? Tau.back() : Tau.front();
    }
    const size_t b = static_cast<size_t>(it - S.begin()), a = b - 1;
    const double w = S[b] > S[a] ? (v - S[a]) / (S[b] - S[a]) : 1;
    return Tau[a] + w * (Tau[b] - Tau[a]);
  }
};

// ---- The reference's rays and ray / tetrahedron clipping ---------------------------------------
// PsiReferenceRaycaster.cxx keeps these private; they are repeated here unchanged in substance,
// and Check() compares the result with psi::RenderReference pixel by pixel.

Vec3 Transform(const std::array<double, 16>& m, double x, double y, double z)
{
  double o[4];
  for (int r = 0; r < 4; ++r)
  {
    o[r] = m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
  }
  return { { o[0] / o[3], o[1] / o[3], o[2] / o[3] } };
}

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

// Pixel (i, j)'s ray: from the near plane `o` along the unit direction `d`, `len` to the far plane.
struct PixelRay
{
  Vec3 o, d;
  double len;
};

PixelRay RayOf(const SceneFile& cam, int i, int j)
{
  PixelRay ray;
  const double x = (i + 0.5) / cam.Width * 2 - 1, y = (j + 0.5) / cam.Height * 2 - 1;
  ray.o = Transform(cam.NdcToWorld, x, y, -1);
  const Vec3 f = Transform(cam.NdcToWorld, x, y, 1);
  ray.d = psi::Sub(f, ray.o);
  ray.len = std::sqrt(psi::Dot(ray.d, ray.d));
  ray.d = { { ray.d[0] / ray.len, ray.d[1] / ray.len, ray.d[2] / ray.len } };
  return ray;
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

TetGeometry MakeTet(const psi::ReferenceScene& sc, const std::array<int, 4>& t)
{
  TetGeometry g{};
  Vec3 V[4];
  for (int i = 0; i < 4; ++i)
  {
    V[i] = sc.Points[t[i]];
  }
  const Vec3 e1 = psi::Sub(V[1], V[0]), e2 = psi::Sub(V[2], V[0]), e3 = psi::Sub(V[3], V[0]);
  const double det = psi::Dot(e1, psi::Cross(e2, e3));
  g.Valid = std::abs(det) > 0 && std::isfinite(det);
  if (!g.Valid)
  {
    return g;
  }
  for (int i = 0; i < 4; ++i)
  {
    const Vec3 &a = V[(i + 1) % 4], &b = V[(i + 2) % 4], &c = V[(i + 3) % 4];
    Vec3 n = psi::Cross(psi::Sub(b, a), psi::Sub(c, a));
    if (psi::Dot(n, psi::Sub(V[i], a)) > 0)
    {
      n = { { -n[0], -n[1], -n[2] } };
    }
    g.Normal[i] = n;
    g.Anchor[i] = a;
  }
  // Gradient: [e1 e2 e3]^T g = ds by Cramer's rule.
  const double ds[3] = { sc.Scalars[t[1]] - sc.Scalars[t[0]], sc.Scalars[t[2]] - sc.Scalars[t[0]],
    sc.Scalars[t[3]] - sc.Scalars[t[0]] };
  const Vec3 c23 = psi::Cross(e2, e3), c31 = psi::Cross(e3, e1), c12 = psi::Cross(e1, e2);
  for (int k = 0; k < 3; ++k)
  {
    g.Gradient[k] = (ds[0] * c23[k] + ds[1] * c31[k] + ds[2] * c12[k]) / det;
  }
  g.Origin = V[0];
  g.S0 = sc.Scalars[t[0]];
  return g;
}

// The pixels (i0..i1, j0..j1) a tetrahedron may cover: its screen box; every pixel when it
// reaches behind the near plane.
std::array<int, 4> ScreenBox(const psi::ReferenceScene& sc, const std::array<int, 4>& t,
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

// One fragment: the segment [t0, t1] of a pixel's ray inside one tetrahedron, the scalar s0, s1
// at its ends.
struct Fragment
{
  double t0, t1, s0, s1;
};

bool Clip(const TetGeometry& g, const PixelRay& ray, Fragment& f)
{
  double tin = 0, tout = ray.len;
  bool hit = true;
  for (int k = 0; k < 4 && hit; ++k)
  {
    const double den = psi::Dot(g.Normal[k], ray.d);
    const double num = psi::Dot(g.Normal[k], psi::Sub(g.Anchor[k], ray.o));
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
  auto scalarAt = [&](double t) {
    const Vec3 p = { { ray.o[0] + t * ray.d[0], ray.o[1] + t * ray.d[1],
      ray.o[2] + t * ray.d[2] } };
    return g.S0 + psi::Dot(g.Gradient, psi::Sub(p, g.Origin));
  };
  f = { tin, tout, scalarAt(tin), scalarAt(tout) };
  return true;
}

// Every pixel's fragments, front to back.
std::vector<std::vector<Fragment>> PixelFragments(
  const psi::ReferenceScene& sc, const SceneFile& cam)
{
  const int W = cam.Width, H = cam.Height;
  std::vector<std::vector<Fragment>> pixels(static_cast<size_t>(W) * H);
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
        Fragment f;
        if (Clip(g, RayOf(cam, i, j), f))
        {
          pixels[static_cast<size_t>(j) * W + i].push_back(f);
        }
      }
    }
  }
  for (auto& list : pixels)
  {
    std::sort(list.begin(), list.end(),
      [](const Fragment& a, const Fragment& b) { return a.t0 < b.t0; });
  }
  return pixels;
}

// ---- Front to back along one ray ----------------------------------------------------------------

struct RayTally
{
  double Alpha = 0;                          // accumulated opacity at the ray's end
  size_t Fragments = 0;                      // segments through tetrahedra
  double Length = 0;                         // ray length inside the mesh
  double TSat[NumThresholds];                // where alpha first reaches each threshold
  size_t FragmentsBehind[NumThresholds] = {}; // fragments starting at or behind TSat
  double LengthBehind[NumThresholds] = {};
};

// Walks the fragments front to back. Within a piece between breakpoints tau is linear, from
// tau_f to tau_b over length D, so the optical depth from the piece's front is
//   E(u) = tau_f D u + (tau_b - tau_f) D u^2 / 2,   u in [0, 1],
// and with alpha_0 accumulated in front of it, alpha reaches a where
//   1 - (1 - alpha_0) exp(-E(u)) = a,   i.e.   E(u) = ln((1 - alpha_0) / (1 - a)).
RayTally Walk(const std::vector<Fragment>& fragments, const Attenuation& tau)
{
  RayTally r;
  std::fill(r.TSat, r.TSat + NumThresholds, std::numeric_limits<double>::infinity());
  const std::vector<double>& bps = tau.S;
  std::vector<double> ts;
  r.Fragments = fragments.size();
  for (const Fragment& f : fragments)
  {
    r.Length += f.t1 - f.t0;
    // The reference's split points: every breakpoint strictly between the end scalars.
    ts.assign(1, f.t0);
    const double smin = std::min(f.s0, f.s1), smax = std::max(f.s0, f.s1);
    for (auto it = std::upper_bound(bps.begin(), bps.end(), smin); it != bps.end() && *it < smax;
         ++it)
    {
      ts.push_back(f.t0 + (f.t1 - f.t0) * (*it - f.s0) / (f.s1 - f.s0));
    }
    ts.push_back(f.t1);
    std::sort(ts.begin(), ts.end());
    for (size_t k = 0; k + 1 < ts.size(); ++k)
    {
      const double sa = f.s0 + (f.s1 - f.s0) * (ts[k] - f.t0) / (f.t1 - f.t0);
      const double sb = f.s0 + (f.s1 - f.s0) * (ts[k + 1] - f.t0) / (f.t1 - f.t0);
      const double D = ts[k + 1] - ts[k];
      const double taufD = tau(sa) * D, taubD = tau(sb) * D;
      for (int a = 0; a < NumThresholds; ++a)
      {
        if (r.TSat[a] < std::numeric_limits<double>::infinity())
        {
          continue;
        }
        const double cut = std::log((1 - r.Alpha) / (1 - Thresholds[a]));
        if (0.5 * (taufD + taubD) >= cut)
        {
          r.TSat[a] = ts[k] + D * psi::TruncationPoint(taufD, 0.5 * (taubD - taufD), cut);
        }
      }
      // The piece's opacity, 1 - zeta (Moreland & Angel 2004 Eq. 8), composited as the
      // reference's Over does.
      const double alpha = -std::expm1(-0.5 * (taubD + taufD));
      r.Alpha += (1 - r.Alpha) * alpha;
    }
  }
  for (const Fragment& f : fragments)
  {
    for (int a = 0; a < NumThresholds; ++a)
    {
      r.FragmentsBehind[a] += f.t0 >= r.TSat[a];
      r.LengthBehind[a] += std::max(0.0, f.t1 - std::max(f.t0, r.TSat[a]));
    }
  }
  return r;
}

// ---- The walk against psi::RenderReference ------------------------------------------------------
// With a white luminance the reference's color is its accumulated opacity (Moreland & Angel 2004
// Eq. 7 with L_f = L_b = 1 gives 1 - zeta), which must be the walk's alpha. With a constant small
// attenuation kappa and no breakpoints every segment is one piece, integrated after one pair of
// transfer-function calls (so half the calls count the fragments), and the color is
// 1 - exp(-kappa length), which gives each pixel's length inside the mesh.
struct CheckResult
{
  double MaxAlphaError = 0;          // |reference alpha - walk alpha|, largest over pixels
  double MaxLengthError = 0;         // relative, largest over pixels
  size_t ReferenceFragments = 0;     // segments the reference integrated
};

CheckResult Check(const psi::ReferenceScene& scene, const SceneFile& s, const Attenuation& tau,
  const std::vector<RayTally>& tallies, double extent)
{
  psi::ReferenceCamera cam;
  cam.Width = s.Width;
  cam.Height = s.Height;
  cam.NdcToWorld = s.NdcToWorld;
  CheckResult c;

  psi::ReferenceScene white = scene;
  white.Transfer = [&tau](double v, double out[4]) {
    out[0] = out[1] = out[2] = 1;
    out[3] = tau(v);
  };
  white.Breakpoints = tau.S;
  const std::vector<double> alphaImage = psi::RenderReference(white, cam);
  for (size_t px = 0; px < tallies.size(); ++px)
  {
    c.MaxAlphaError = std::max(c.MaxAlphaError, std::abs(alphaImage[3 * px] - tallies[px].Alpha));
  }

  const double kappa = 1e-3 / extent; // optical depth at most ~1e-3 on any ray
  size_t calls = 0;
  psi::ReferenceScene thin = std::move(white);
  thin.Transfer = [kappa, &calls](double, double out[4]) {
    ++calls;
    out[0] = out[1] = out[2] = 1;
    out[3] = kappa;
  };
  thin.Breakpoints.clear();
  const std::vector<double> lengthImage = psi::RenderReference(thin, cam);
  c.ReferenceFragments = calls / 2;
  for (size_t px = 0; px < tallies.size(); ++px)
  {
    const double length = -std::log1p(-lengthImage[3 * px]) / kappa;
    c.MaxLengthError = std::max(c.MaxLengthError,
      std::abs(length - tallies[px].Length) / std::max(tallies[px].Length, 1e-6 * extent));
  }
  return c;
}

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3 || (argc == 4 && std::strcmp(argv[3], "--no-check") != 0) || argc > 4)
  {
    std::cerr << "usage: bench_saturation MESH.vtu SCENE.txt [--no-check]\n";
    return 2;
  }
  const bool check = argc < 4;
  SceneFile s;
  if (!ReadScene(argv[2], s))
  {
    std::cerr << "bench_saturation: cannot use the scene file " << argv[2] << "\n";
    return 2;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(argv[1]))
  {
    std::cerr << "bench_saturation: cannot read the mesh " << argv[1] << "\n";
    return 2;
  }
  reader->SetFileName(argv[1]);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(reader->GetOutputPort());
  tets->TetrahedraOnlyOn();
  tets->Update();
  psi::ReferenceScene scene;
  if (!GatherMesh(tets->GetOutput(), s, scene))
  {
    return 2;
  }
  double bounds[6];
  tets->GetOutput()->GetBounds(bounds);
  const double extent = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const Attenuation tau(s);

  const auto start = std::chrono::steady_clock::now();
  std::vector<RayTally> tallies;
  {
    const std::vector<std::vector<Fragment>> pixels = PixelFragments(scene, s);
    tallies.reserve(pixels.size());
    for (const auto& fragments : pixels)
    {
      tallies.push_back(Walk(fragments, tau));
    }
  }
  const double walkSeconds = Seconds(start);

  // Sums over all pixels.
  size_t fragments = 0, hitPixels = 0, saturated[NumThresholds] = {};
  size_t fragmentsBehind[NumThresholds] = {};
  double length = 0, alphaSum = 0, lengthBehind[NumThresholds] = {};
  for (const RayTally& r : tallies)
  {
    if (r.Fragments == 0)
    {
      continue;
    }
    ++hitPixels;
    fragments += r.Fragments;
    length += r.Length;
    alphaSum += r.Alpha;
    for (int a = 0; a < NumThresholds; ++a)
    {
      saturated[a] += r.TSat[a] < std::numeric_limits<double>::infinity();
      fragmentsBehind[a] += r.FragmentsBehind[a];
      lengthBehind[a] += r.LengthBehind[a];
    }
  }
  std::printf("tetrahedra %zu\nsize %d %d\nunit %.9g\n", scene.Tets.size(), s.Width, s.Height,
    s.Unit);
  std::printf("pixels_hit %zu\nfragments %zu\nfragments_per_hit_pixel %.2f\n", hitPixels,
    fragments, hitPixels ? double(fragments) / hitPixels : 0.0);
  std::printf("mean_alpha_hit_pixels %.6f\n", hitPixels ? alphaSum / hitPixels : 0.0);
  for (int a = 0; a < NumThresholds; ++a)
  {
    const double pct = 100.0 * double(fragmentsBehind[a]) / std::max<size_t>(fragments, 1);
    std::printf("threshold %g: pixels_saturated_pct %.3f fragments_behind_pct %.3f "
                "length_behind_pct %.3f\n",
      Thresholds[a], hitPixels ? 100.0 * double(saturated[a]) / hitPixels : 0.0, pct,
      length > 0 ? 100.0 * lengthBehind[a] / length : 0.0);
  }
  std::printf("walk_seconds %.3f\n", walkSeconds);
  if (!check)
  {
    return 0;
  }
  const auto checkStart = std::chrono::steady_clock::now();
  const CheckResult c = Check(scene, s, tau, tallies, extent);
  std::printf("check_reference_fragments %zu\ncheck_max_alpha_error %.3g\n"
              "check_max_length_relative_error %.3g\ncheck_seconds %.3f\n",
    c.ReferenceFragments, c.MaxAlphaError, c.MaxLengthError, Seconds(checkStart));
  // The reference stops a ray once its opacity exceeds 1 - 1e-12.
  const bool same =
    c.ReferenceFragments == fragments && c.MaxAlphaError < 1e-9 && c.MaxLengthError < 1e-6;
  std::printf("check %s\n", same ? "passed" : "FAILED");
  return same ? 0 : 1;
}
