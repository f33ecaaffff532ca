// Benchmark (not a test): how much of a projected-tetrahedra frame lies behind the point where its
// pixel is already opaque, the work that front-to-back compositing with early ray termination
// (Levoy 1990, "Efficient ray tracing of volume data", adaptive ray termination) could skip.
//
// A projected-tetrahedra renderer shades one fragment per tetrahedron and pixel whose center ray
// crosses it (Shirley & Tuchman 1990), so a pixel's fragments are its ray's segments through the
// tetrahedra. Each pixel's ray is walked front to back as the exact reference does
// (PsiReferenceRaycaster: its rays from the near plane and its ray / face-plane clipping,
// psi::ReferencePixelPieces; each segment split at the transfer function's breakpoints, tau
// linear on each piece), and the accumulated opacity after optical depth E along the ray is
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
#include "PsiReferenceSceneFile.h"

#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
// The opacity thresholds a_k.
constexpr int NumThresholds = 2;
constexpr double Thresholds[NumThresholds] = { 0.99, 0.999 };

// ---- Attenuation: tau(s) = opacity(s) / unit, the table linear between rows, clamped ---------

struct Attenuation
{
  std::vector<double> S, Tau; // the table's rows; every S is a breakpoint

  explicit Attenuation(const psi::ReferenceSceneFile& s)
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

// ---- The reference's rays -----------------------------------------------------------------------

// One fragment: the segment [t0, t1] of a pixel's ray inside one tetrahedron, the scalar s0, s1 at
// its ends, as the reference clips it.
using Fragment = psi::ReferencePiece;

// Every pixel's fragments, front to back.
std::vector<std::vector<Fragment>> PixelFragments(
  const psi::ReferenceScene& sc, const psi::ReferenceCamera& cam)
{
  std::vector<std::vector<Fragment>> pixels = psi::ReferencePixelPieces(sc, cam);
  for (auto& list : pixels)
  {
    std::sort(
      list.begin(), list.end(), [](const Fragment& a, const Fragment& b) { return a.t0 < b.t0; });
  }
  return pixels;
}

// ---- Front to back along one ray ----------------------------------------------------------------

struct RayTally
{
  double Alpha = 0;                           // accumulated opacity at the ray's end
  size_t Fragments = 0;                       // segments through tetrahedra
  double Length = 0;                          // ray length inside the mesh
  double TSat[NumThresholds];                 // where alpha first reaches each threshold
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
// With a white luminance over a black background the reference's color is its accumulated
// opacity (Moreland & Angel 2004 Eq. 7 with L_f = L_b = 1 gives 1 - zeta), which must be the
// walk's alpha. With a constant small
// attenuation kappa and no breakpoints every segment is one piece, integrated after one pair of
// transfer-function calls (so half the calls count the fragments), and the color is
// 1 - exp(-kappa length), which gives each pixel's length inside the mesh.
struct CheckResult
{
  double MaxAlphaError = 0;      // |reference alpha - walk alpha|, largest over pixels
  double MaxLengthError = 0;     // relative, largest over pixels
  size_t ReferenceFragments = 0; // segments the reference integrated
};

CheckResult Check(const psi::ReferenceScene& scene, const psi::ReferenceCamera& camera,
  const Attenuation& tau, const std::vector<RayTally>& tallies, double extent)
{
  psi::ReferenceCamera cam = camera;
  cam.Background = { { 0, 0, 0 } };
  CheckResult c;

  psi::ReferenceScene white = scene;
  white.Transfer = [&tau](double v, double out[4])
  {
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
  thin.Transfer = [kappa, &calls](double, double out[4])
  {
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

// The scene file, the mesh's tetrahedra with their scalars, and the length of the mesh's bounding
// box diagonal: an empty string, or why they cannot be read.
std::string ReadInput(const char* meshPath, const char* scenePath, psi::ReferenceSceneFile& s,
  psi::ReferenceScene& scene, double& extent)
{
  std::string why = psi::ReadReferenceSceneFile(scenePath, s);
  if (!why.empty())
  {
    return why;
  }
  const vtkSmartPointer<vtkUnstructuredGrid> grid = psi::ReadTetrahedralGrid(meshPath);
  if (!grid)
  {
    return "cannot read the mesh " + std::string(meshPath);
  }
  why = psi::GatherReferenceMesh(grid, s, scene);
  if (!why.empty())
  {
    return why;
  }
  double bounds[6];
  grid->GetBounds(bounds);
  extent = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  return std::string();
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
  psi::ReferenceSceneFile s;
  psi::ReferenceScene scene;
  double extent = 0;
  const std::string why = ReadInput(argv[1], argv[2], s, scene, extent);
  if (!why.empty())
  {
    std::cerr << "bench_saturation: " << why << "\n";
    return 2;
  }
  const psi::ReferenceCamera cam = psi::ReferenceCameraOf(s);
  const Attenuation tau(s);

  const auto start = std::chrono::steady_clock::now();
  std::vector<RayTally> tallies;
  {
    const std::vector<std::vector<Fragment>> pixels = PixelFragments(scene, cam);
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
  std::printf(
    "tetrahedra %zu\nsize %d %d\nunit %.9g\n", scene.Tets.size(), s.Width, s.Height, s.Unit);
  std::printf("pixels_hit %zu\nfragments %zu\nfragments_per_hit_pixel %.2f\n", hitPixels, fragments,
    hitPixels ? double(fragments) / hitPixels : 0.0);
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
  const CheckResult c = Check(scene, cam, tau, tallies, extent);
  std::printf("check_reference_fragments %zu\ncheck_max_alpha_error %.3g\n"
              "check_max_length_relative_error %.3g\ncheck_seconds %.3f\n",
    c.ReferenceFragments, c.MaxAlphaError, c.MaxLengthError, Seconds(checkStart));
  // The reference stops a ray once its opacity exceeds 1 - 1e-12.
  const bool same =
    c.ReferenceFragments == fragments && c.MaxAlphaError < 1e-9 && c.MaxLengthError < 1e-6;
  std::printf("check %s\n", same ? "passed" : "FAILED");
  return same ? 0 : 1;
}
