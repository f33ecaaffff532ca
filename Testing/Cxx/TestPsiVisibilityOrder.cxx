// The visibility order the mapper draws, checked against an exact criterion instead of an image:
// compositing back to front is right exactly when, along every ray, each tetrahedron the ray
// crosses is drawn before the ones in front of it (Williams 1992; Maximo et al. 2010 §3.1).
// Rays through a jittered grid of pixels are intersected exactly (double precision) with every
// tetrahedron, and each pair of successive cells along a ray is checked in the drawn order. One
// swapped pair of overlapping cells is one violation, so this sees a few misordered neighbours
// that an 8-bit image of a smooth field would hide.
//  - MPVONC (the default) on convex Kuhn and 5-tetrahedra grids, perspective and parallel: no
//    violation (Williams 1992 §4-5: exact for acyclic convex meshes; these grids are Delaunay,
//    and Delaunay meshes are acyclic, Edelsbrunner 1990).
//  - The centroid sort (Maximo et al. 2010 §3.1) against its own definition: keys descending
//    (distance to the eye, or depth along the view direction), equal keys by ascending id; and
//    MPVONC's equal depths by ascending id (the rule that makes its order reproducible).
// Needs an X server (run under xvfb-run).
#include "PsiTestCheck.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"
#include "PsiVec3.h"
#include "PsiVisibilitySort.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkCamera.h"
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
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace
{
using psi::Cross;
using psi::Dot;
using psi::Sub;
using psi::Vec3;

// A structured grid of n^3 cells (spacing 1, corner at the origin), split into Kuhn tetrahedra
// (6 per cube) or by vtkDataSetTriangleFilter.
void MakeGridTets(vtkUnstructuredGrid* grid, int n, bool kuhn)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n + 1, n + 1, n + 1);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double p[3];
    image->GetPoint(i, p);
    s->InsertNextValue(std::sin(p[0] + 0.3 * p[1]) + 0.2 * p[2]);
  }
  image->GetPointData()->SetScalars(s);
  psitest::TetrahedralizeImage(image, kuhn, grid);
}

struct Tet
{
  Vec3 Normal[4], Anchor[4]; // outward face planes
};

std::vector<Tet> Tetrahedra(vtkUnstructuredGrid* grid)
{
  std::vector<Tet> tets(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids;
    vtkIdType n;
    grid->GetCellPoints(c, n, ids);
    Vec3 V[4];
    for (int i = 0; i < 4; ++i)
    {
      grid->GetPoint(ids[i], V[i].data());
    }
    for (int i = 0; i < 4; ++i)
    {
      const Vec3 &a = V[(i + 1) % 4], &b = V[(i + 2) % 4], &cc = V[(i + 3) % 4];
      Vec3 nn = Cross(Sub(b, a), Sub(cc, a));
      if (Dot(nn, Sub(V[i], a)) > 0)
      {
        nn = { { -nn[0], -nn[1], -nn[2] } };
      }
      tets[c].Normal[i] = nn;
      tets[c].Anchor[i] = a;
    }
  }
  return tets;
}

// Parameter interval of the ray o + t d inside tetrahedron `t`; false when it misses.
bool Clip(const Tet& t, const Vec3& o, const Vec3& d, double& tin, double& tout)
{
  tin = -1e300;
  tout = 1e300;
  for (int i = 0; i < 4; ++i)
  {
    const double den = Dot(t.Normal[i], d), num = Dot(t.Normal[i], Sub(t.Anchor[i], o));
    if (den == 0)
    {
      if (num < 0)
      {
        return false;
      }
      continue;
    }
    if (den < 0)
    {
      tin = std::max(tin, num / den); // entering through face i
    }
    else
    {
      tout = std::min(tout, num / den);
    }
  }
  return tout > tin + 1e-7;
}

// Along rays through a jittered grid of the camera's pixels: pairs of successive cells drawn in
// the wrong order (the front one first). Also counts the pairs checked.
size_t RayViolations(
  vtkCamera* cam, const std::vector<Tet>& tets, const std::vector<uint32_t>& order, size_t& checked)
{
  std::vector<size_t> pos(tets.size(), 0);
  for (size_t k = 0; k < order.size(); ++k)
  {
    pos[order[k]] = k;
  }
  vtkNew<vtkMatrix4x4> m;
  m->DeepCopy(cam->GetCompositeProjectionTransformMatrix(1.0, -1, 1));
  m->Invert();
  auto unproject = [&](double x, double y, double z)
  {
    double in[4] = { x, y, z, 1 }, out[4];
    m->MultiplyPoint(in, out);
    return Vec3{ { out[0] / out[3], out[1] / out[3], out[2] / out[3] } };
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(0, 1);
  constexpr int N = 80;
  size_t bad = 0;
  checked = 0;
  std::vector<std::array<double, 3>> hits; // tin, tout, tet
  for (int j = 0; j < N; ++j)
  {
    for (int i = 0; i < N; ++i)
    {
      const double x = 2 * (i + jitter(rng)) / N - 1, y = 2 * (j + jitter(rng)) / N - 1;
      const Vec3 o = unproject(x, y, -1);
      const Vec3 d = Sub(unproject(x, y, 1), o);
      hits.clear();
      for (size_t t = 0; t < tets.size(); ++t)
      {
        double tin, tout;
        if (Clip(tets[t], o, d, tin, tout))
        {
          hits.push_back({ { tin, tout, double(t) } });
        }
      }
      std::sort(hits.begin(), hits.end());
      for (size_t k = 0; k + 1 < hits.size(); ++k)
      {
        ++checked;
        bad += pos[size_t(hits[k + 1][2])] > pos[size_t(hits[k][2])];
      }
    }
  }
  return bad;
}

// The centroid sort against its definition, on `grid` for the eye or view direction `eye`.
void CheckCentroidDefinition(vtkUnstructuredGrid* grid, const double eye[3], bool parallel)
{
  psi::TetMesh mesh;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[3];
    grid->GetPoint(i, p);
    mesh.Points4.insert(mesh.Points4.end(), { float(p[0]), float(p[1]), float(p[2]), 0.0f });
  }
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids;
    vtkIdType n;
    grid->GetCellPoints(c, n, ids);
    mesh.Tets.insert(
      mesh.Tets.end(), { uint32_t(ids[0]), uint32_t(ids[1]), uint32_t(ids[2]), uint32_t(ids[3]) });
  }
  std::unique_ptr<psi::VisibilitySort> sort = psi::NewCentroidSort();
  sort->SetMesh(&mesh, {});
  std::vector<uint32_t> order;
  sort->Sort(eye, parallel, order);
  // The key as the sort defines it: float centroid; squared distance to the eye, or the depth
  // along the view direction. Larger is farther.
  auto key = [&](uint32_t t)
  {
    float s[3] = { 0, 0, 0 };
    for (int v = 0; v < 4; ++v)
    {
      for (int a = 0; a < 3; ++a)
      {
        s[a] += mesh.Points4[4 * mesh.Tets[4 * t + v] + a];
      }
    }
    const float c[3] = { 0.25f * s[0], 0.25f * s[1], 0.25f * s[2] };
    const float e[3] = { float(eye[0]), float(eye[1]), float(eye[2]) };
    if (parallel)
    {
      return c[0] * e[0] + c[1] * e[1] + c[2] * e[2];
    }
    const float dx = c[0] - e[0], dy = c[1] - e[1], dz = c[2] - e[2];
    return dx * dx + dy * dy + dz * dz;
  };
  size_t wrong = 0, ties = 0;
  PSI_CHECK(order.size() == mesh.NumberOfTets(), "centroid order has %zu of %zu cells",
    order.size(), mesh.NumberOfTets());
  for (size_t k = 0; k + 1 < order.size(); ++k)
  {
    const float a = key(order[k]), b = key(order[k + 1]);
    ties += a == b;
    wrong += a < b || (a == b && order[k] > order[k + 1]);
  }
  PSI_CHECK(wrong == 0, "centroid order (%s): %zu successive pairs out of key/id order",
    parallel ? "parallel" : "perspective", wrong);
  std::printf("centroid sort (%s): %zu cells by key, %zu equal-key neighbours by id\n",
    parallel ? "parallel" : "perspective", order.size(), ties);
}

// MPVONC's documented tie rule (PsiMPVONCSort.cxx DepthKey: farthest first, ties by id), which
// makes the order reproducible: unconnected congruent tetrahedra side by side at one depth are
// all ready at once with equal keys, and must come in id order, in both projections.
void CheckMPVONCTies()
{
  psi::TetMesh mesh;
  const int n = 12;
  for (int t = 0; t < n; ++t)
  {
    const float x = 3.0f * static_cast<float>(t);
    const float p[4][3] = { { x, 0, 0 }, { x + 1, 0, 0 }, { x, 1, 0 }, { x, 0, 1 } };
    for (const auto& q : p)
    {
      mesh.Points4.insert(mesh.Points4.end(), { q[0], q[1], q[2], 0.0f });
    }
    for (uint32_t v = 0; v < 4; ++v)
    {
      mesh.Tets.push_back(4 * static_cast<uint32_t>(t) + v);
    }
  }
  std::unique_ptr<psi::VisibilitySort> sort = psi::NewMPVONCSort();
  sort->SetMesh(&mesh, {});
  const double dir[3] = { 0, 0, -1 };
  std::vector<uint32_t> order;
  sort->Sort(dir, true, order);
  bool byId = order.size() == size_t(n);
  for (size_t k = 0; byId && k < order.size(); ++k)
  {
    byId = order[k] == k;
  }
  PSI_CHECK(byId, "MPVONC: equal depths not in id order (first %u, last %u)",
    order.empty() ? 0u : order.front(), order.empty() ? 0u : order.back());
}
} // namespace

int main()
{
  psitest::TransferFunction tf;
  psitest::BlueToYellow(tf.Color, -2, 3);
  psitest::LinearOpacity(tf.Opacity, -2, 3, 0.2, 1.0);
  vtkNew<vtkPsiVolumeMapper> mapper;
  mapper->SetRecordDrawOrder(true); // what each frame streams to the GPU
  psitest::VolumeView view(64, 64, mapper, tf.Property);
  vtkRenderWindow* win = view.Window;
  vtkRenderer* ren = view.Renderer;
  vtkCamera* cam = ren->GetActiveCamera();

  struct View
  {
    double Eye[3];
    bool Parallel;
  };
  const View views[] = { { { 13, 9, 17 }, false }, { { -6, 14, -9 }, false },
    { { 2.7, -11, 4.1 }, false }, { { 9, -7, 12 }, true } };
  for (const bool kuhn : { true, false })
  {
    vtkNew<vtkUnstructuredGrid> grid;
    MakeGridTets(grid, kuhn ? 6 : 7, kuhn);
    const std::vector<Tet> tets = Tetrahedra(grid);
    mapper->SetInputData(grid);
    for (const View& v : views)
    {
      const double c = kuhn ? 3.0 : 3.5;
      cam->SetFocalPoint(c, c, c);
      cam->SetPosition(c + v.Eye[0], c + v.Eye[1], c + v.Eye[2]);
      cam->SetViewUp(0, 1, 0);
      cam->SetParallelProjection(v.Parallel);
      ren->ResetCamera();
      win->Render();
      // farthest first; nearest first when the frame composited front to back
      std::vector<uint32_t> order = mapper->GetLastDrawOrder();
      if (mapper->GetLastUsedEarlyRayTermination())
      {
        std::reverse(order.begin(), order.end());
      }
      std::vector<uint32_t> sorted(order);
      std::sort(sorted.begin(), sorted.end());
      bool permutation = sorted.size() == tets.size();
      for (size_t k = 0; permutation && k < sorted.size(); ++k)
      {
        permutation = sorted[k] == k;
      }
      PSI_CHECK(permutation, "drawn order is not a permutation of the %zu cells", tets.size());
      if (!permutation)
      {
        continue;
      }
      size_t checked = 0;
      const size_t bad = RayViolations(cam, tets, order, checked);
      std::printf("%s grid, %s view: %zu cells, %zu successive pairs along rays, %zu misordered\n",
        kuhn ? "Kuhn" : "5-tetrahedra", v.Parallel ? "parallel" : "perspective", tets.size(),
        checked, bad);
      PSI_CHECK(checked > 10 * tets.size(), "too few pairs checked (%zu)", checked);
      PSI_CHECK(bad == 0, "MPVONC drawn order: %zu pairs along rays drawn front first", bad);
    }
    // The centroid sort's definition, with many equal keys (grid cells seen along an axis).
    const double eye[3] = { 3.0, 3.0, 40.0 }, axis[3] = { 0, 0, -1 },
                 skew[3] = { 0.48, 0.6, -0.64 };
    CheckCentroidDefinition(grid, eye, false);
    CheckCentroidDefinition(grid, axis, true);
    CheckCentroidDefinition(grid, skew, true);
  }
  CheckMPVONCTies();
  return psitest::Report("TestPsiVisibilityOrder");
}
