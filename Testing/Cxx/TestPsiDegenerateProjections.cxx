// Degenerate projections on the GPU against the exact CPU ray integration (PsiReferenceRaycaster).
//
// The PTINT truth table (Marroquim et al. 2006, Fig. 3 and §4.1) has 24 class-3 entries (a vertex
// projects onto an edge) and 12 class-4 entries (two vertices project onto one point). Generic
// views never reach them exactly, so the other image tests cannot tell whether the geometry
// shader's copy of these entries is right. Here:
//  1. every degenerate entry: one tetrahedron per entry, its (x, y) taken from a lattice
//     configuration with that sign pattern, seen in an axis-aligned parallel view whose
//     projection is exact in float (scale 1/16, integer coordinates), so the shader's orientation
//     tests see exactly the degenerate signs;
//  2. single tetrahedra in perspective with two vertices on one ray and a vertex on the ray plane
//     of an edge (exact: the view-space points are multiples of each other, or share y = 0);
//  3. tetrahedralized structured grids (Kuhn and 5-tetrahedra splits) in axis-aligned parallel
//     and perspective views, the eye on a grid line: collinear and coincident projections
//     everywhere, as in the head-on views of structured data.
// Needs an X server (run under xvfb-run). Usage: TestPsiDegenerateProjections [output-dir]
#include "PsiProjectionClasses.h"
#include "PsiReferenceRaycaster.h"
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace
{
constexpr int W = 256, H = 256;

struct Errors
{
  double Mean = 0, Max = 0;
  int Bad = 0;           ///< pixels off by more than BadLevel, with their four neighbours
  int Covered = 0;       ///< pixels the reference shows the volume in
  std::vector<double> E; ///< per-pixel max channel error
};
constexpr double BadLevel = 0.08;

// Renders the window, and the same camera with the CPU reference; per-pixel errors.
Errors Compare(const std::string& name, vtkRenderWindow* win, vtkRenderer* ren,
  vtkUnstructuredGrid* grid, vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity,
  double unit, const std::string& outDir)
{
  const std::vector<double> gpu = psitest::GrabRGB(win);
  const double* bg = ren->GetBackground();
  const std::vector<double> ref = psi::RenderReference(
    psitest::MakeReferenceScene(grid, color, opacity, unit), psitest::ReferenceCameraOf(ren, W, H));
  Errors r;
  r.E.assign(W * H, 0.0);
  std::vector<double> diff(ref.size());
  for (int i = 0; i < W * H; ++i)
  {
    double covered = 0;
    for (int k = 0; k < 3; ++k)
    {
      const double e = std::abs(gpu[3 * i + k] - std::min(1.0, std::max(0.0, ref[3 * i + k])));
      r.E[i] = std::max(r.E[i], e);
      r.Mean += e;
      diff[3 * i + k] = 8 * e;
      covered += std::abs(ref[3 * i + k] - bg[k]);
    }
    r.Max = std::max(r.Max, r.E[i]);
    r.Covered += covered > 2.0 / 255;
  }
  // A ray exactly in a face plane (a pixel centre on a projected edge) may see either side: such
  // pixels form lines one pixel wide, which the erosion by the four neighbours removes. A wrong
  // fan or thickness is wrong over an area.
  std::vector<double> eroded(W * H, 0.0);
  for (int j = 1; j + 1 < H; ++j)
  {
    for (int i = 1; i + 1 < W; ++i)
    {
      const int k = j * W + i;
      eroded[k] = std::min({ r.E[k], r.E[k - 1], r.E[k + 1], r.E[k - W], r.E[k + W] });
      r.Bad += eroded[k] > BadLevel;
    }
  }
  r.E = eroded;
  r.Mean /= 3.0 * W * H;
  if (!outDir.empty())
  {
    psitest::WritePng(outDir + "/" + name + "_gpu.png", gpu, W, H);
    psitest::WritePng(outDir + "/" + name + "_ref.png", ref, W, H);
    psitest::WritePng(outDir + "/" + name + "_diff8x.png", diff, W, H);
  }
  std::printf("%-26s mean error %.5f  max %.4f  pixels off by > %.2f: %d of %d covered\n",
    name.c_str(), r.Mean, r.Max, BadLevel, r.Bad, r.Covered);
  std::fflush(stdout);
  return r;
}

// A grid of loose tetrahedra: 4 points each, scalars 0.1, 0.9, 0.45, 0.7 at the vertices.
void AddTet(vtkPoints* pts, vtkDoubleArray* s, vtkUnstructuredGrid* g, const double p[4][3])
{
  static const double sv[4] = { 0.1, 0.9, 0.45, 0.7 };
  vtkIdType ids[4];
  for (int v = 0; v < 4; ++v)
  {
    ids[v] = pts->InsertNextPoint(p[v]);
    s->InsertNextValue(sv[v]);
  }
  g->InsertNextCell(VTK_TETRA, 4, ids);
}

double Volume6(const double p[4][3])
{
  double e[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      e[i][k] = p[i + 1][k] - p[0][k];
    }
  }
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
    e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
    e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

// One tetrahedron per class-3 and class-4 entry of the truth table, in a 6 x 6 layout of tiles
// 5 units apart. The (x, y) of each is the largest configuration of the lattice [-2, 2]^2 (the
// one the table is derived from) with that entry's sign pattern, classified on the CPU; z is
// chosen per vertex so that the tetrahedron has volume and depth. Returns the entries used.
std::vector<int> MakeDegenerateTiles(vtkUnstructuredGrid* grid)
{
  std::array<bool, 81> done{};
  std::array<double, 81> best{};
  std::vector<std::array<double, 8>> configs(81);
  for (int code = 0; code < 390625; ++code)
  {
    double x[4], y[4];
    int c = code;
    for (int i = 0; i < 4; ++i)
    {
      x[i] = c % 5 - 2;
      c /= 5;
      y[i] = c % 5 - 2;
      c /= 5;
    }
    const int idx = psi::TruthTableIndex(x, y);
    const int cls = psi::ClassifyProjection(x, y).cls;
    double area = 0; // of the projection's hull: the largest of the four triangles
    for (int m = 0; m < 4; ++m)
    {
      const int a = (m + 1) % 4, b = (m + 2) % 4, c3 = (m + 3) % 4;
      area =
        std::max(area, std::abs((x[b] - x[a]) * (y[c3] - y[a]) - (y[b] - y[a]) * (x[c3] - x[a])));
    }
    if ((cls == 3 || cls == 4) && area > best[idx])
    {
      done[idx] = true;
      best[idx] = area;
      configs[idx] = { { x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3] } };
    }
  }
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  grid->Allocate(36);
  std::vector<int> used;
  static const double zs[4][4] = { { 0, 3, 1, 2 }, { 2, 0, 3, 1 }, { 1, 2, 0, 3 }, { 3, 1, 2, 0 } };
  for (int idx = 0; idx < 81; ++idx)
  {
    if (!done[idx])
    {
      continue;
    }
    const int tile = static_cast<int>(used.size());
    const double ox = 5.0 * (tile % 6) - 12.5, oy = 5.0 * (tile / 6) - 12.5;
    double p[4][3];
    for (const auto& z : zs)
    {
      for (int v = 0; v < 4; ++v)
      {
        p[v][0] = ox + configs[idx][v];
        p[v][1] = oy + configs[idx][4 + v];
        p[v][2] = z[v];
      }
      if (std::abs(Volume6(p)) >= 1)
      {
        break;
      }
    }
    AddTet(pts, s, grid, p);
    used.push_back(idx);
  }
  grid->SetPoints(pts);
  grid->GetPointData()->SetScalars(s);
  return used;
}

// Single tetrahedra for a perspective eye at (0, 0, 20) looking down -z: in view space (z - 20)
// the first has two vertices on one ray ((1, 0.5, -4) and (2, 1, -8)), the second a vertex on the
// ray plane of an edge (all three at y = 0, the middle one between the others' projections).
void MakePerspectiveTets(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  grid->Allocate(2);
  const double a[4][3] = { { 1, 0.5, 16 }, { 2, 1, 12 }, { 3, -1, 14 }, { -1, -2, 13 } };
  const double b[4][3] = { { -2, 0, 16 }, { 1, 0, 12 }, { -1, 2.5, 14 }, { -0.25, 0, 14 } };
  AddTet(pts, s, grid, a);
  AddTet(pts, s, grid, b);
  grid->SetPoints(pts);
  grid->GetPointData()->SetScalars(s);
}

// A structured grid of n^3 unit cells centred on the z axis split into tetrahedra: Kuhn (6 per
// cube around the main diagonal) or vtkDataSetTriangleFilter's alternating split.
void MakeGridTets(vtkUnstructuredGrid* grid, int n, bool kuhn)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n + 1, n + 1, n + 1);
  image->SetOrigin(-n / 2, -n / 2, -n / 2);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double p[3];
    image->GetPoint(i, p);
    s->InsertNextValue(0.5 + 0.45 * std::sin(0.9 * p[0] + 0.4 * p[1]) * std::cos(0.7 * p[2]));
  }
  image->GetPointData()->SetScalars(s);
  psitest::TetrahedralizeImage(image, kuhn, grid);
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string outDir = psitest::ParseArguments(argc, argv);
  psitest::VolumeView view(W, H, nullptr, nullptr); // the volume is added below
  vtkRenderWindow* win = view.Window;
  vtkRenderer* ren = view.Renderer;
  const double unit = 0.75;
  psitest::TransferFunction tf(unit);
  psitest::BlueToYellow(tf.Color, 0.0, 1.0);
  psitest::LinearOpacity(tf.Opacity, 0.0, 1.0, 0.2, 1.0);
  vtkColorTransferFunction* color = tf.Color;
  vtkPiecewiseFunction* opacity = tf.Opacity;
  vtkNew<vtkPsiVolumeMapper> mapper;
  psitest::ApplyRequested(mapper.GetPointer());
  vtkNew<vtkVolume> vol;
  vol->SetMapper(mapper);
  vol->SetProperty(tf.Property);
  ren->AddVolume(vol);
  vtkCamera* cam = ren->GetActiveCamera();
  auto look = [&](double eyeX, double eyeY, double eyeZ, bool parallel)
  {
    cam->SetFocalPoint(eyeX, eyeY, 0);
    cam->SetPosition(eyeX, eyeY, eyeZ);
    cam->SetViewUp(0, 1, 0);
    cam->SetParallelProjection(parallel);
    cam->SetParallelScale(16); // ndc = world / 16: exact in float
    cam->SetViewAngle(40);
    cam->SetClippingRange(1, 60);
  };

  // 1. Every degenerate entry of the truth table, exactly, in parallel projection. A wrong entry
  // draws the wrong fan: a tile with many pixels off.
  {
    vtkNew<vtkUnstructuredGrid> tiles;
    const std::vector<int> entries = MakeDegenerateTiles(tiles);
    PSI_CHECK(entries.size() == 36, "%zu degenerate entries found on the lattice, expected 36",
      entries.size());
    mapper->SetInputData(tiles);
    look(0, 0, 30, true);
    const Errors e = Compare("degenerate_entries", win, ren, tiles, color, opacity, unit, outDir);
    // Per tile: pixels off by more than BadLevel (silhouette pixels can be, by rasterization).
    for (size_t t = 0; t < entries.size(); ++t)
    {
      const double ox = 5.0 * (t % 6) - 12.5, oy = 5.0 * (t / 6) - 12.5;
      int bad = 0;
      for (int j = 0; j < H; ++j)
      {
        for (int i = 0; i < W; ++i)
        {
          const double x = (i + 0.5) / W * 32 - 16, y = (j + 0.5) / H * 32 - 16;
          bad += std::abs(x - ox) < 2.5 && std::abs(y - oy) < 2.5 && e.E[j * W + i] > BadLevel;
        }
      }
      const psi::ProjectionClass& pc = psi::GetProjectionClassTable()[entries[t]];
      PSI_CHECK(bad <= 3, "truth-table entry %d (class %d, roles %d%d%d%d): %d pixels off",
        entries[t], pc.cls, pc.p[0], pc.p[1], pc.p[2], pc.p[3], bad);
    }
    PSI_CHECK(e.Covered > W * H / 8, "degenerate tiles: image nearly empty (%d)", e.Covered);
    PSI_CHECK(e.Mean < 0.003, "degenerate tiles: mean error %g", e.Mean);
  }

  // 2. Single tetrahedra in perspective: two vertices on one ray, a vertex on an edge's ray plane.
  {
    vtkNew<vtkUnstructuredGrid> single;
    MakePerspectiveTets(single);
    mapper->SetInputData(single);
    look(0, 0, 20, false);
    const Errors e = Compare("perspective_single", win, ren, single, color, opacity, unit, outDir);
    PSI_CHECK(e.Covered > W * H / 20, "single tetrahedra: image nearly empty (%d)", e.Covered);
    PSI_CHECK(e.Bad <= 12 && e.Mean < 0.003,
      "single tetrahedra in perspective: %d pixels off, "
      "mean %g",
      e.Bad, e.Mean);
  }

  // 3. Tetrahedralized grids seen along an axis, parallel and with the eye on the grid's centre
  // line (x = y = 0): coincident and collinear projections for every cell touching it.
  for (const bool kuhn : { true, false })
  {
    vtkNew<vtkUnstructuredGrid> grid;
    MakeGridTets(grid, 6, kuhn);
    mapper->SetInputData(grid);
    for (const bool parallel : { true, false })
    {
      look(0, 0, 24, parallel);
      cam->SetParallelScale(4); // ndc = world / 4: exact in float
      cam->SetViewAngle(20);
      const std::string name =
        std::string(kuhn ? "kuhn" : "five") + (parallel ? "_parallel" : "_perspective");
      const Errors e = Compare(name, win, ren, grid, color, opacity, unit, outDir);
      PSI_CHECK(e.Covered > W * H / 4, "%s: image nearly empty (%d)", name.c_str(), e.Covered);
      PSI_CHECK(e.Bad <= W * H / 500 && e.Mean < 0.003, "%s: %d pixels off, mean %g", name.c_str(),
        e.Bad, e.Mean);
    }
  }

  psitest::CheckRequestedProjector(mapper->GetLastUsedProjector());
  return psitest::Report("TestPsiDegenerateProjections");
}
