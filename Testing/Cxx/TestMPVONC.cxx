// Tests of psi::SortMPVONC (Williams 1992) and psi::ComputeTetNeighbors: on convex
// tetrahedralized boxes, from many random perspective and parallel views, no adjacency
// constraint is violated (across every interior face the tetrahedron behind comes first, decided
// here independently with CGAL's exact orientation); disconnected components are ordered by
// depth; a constructed cycle and random cyclic graphs terminate with a permutation and report
// the cycles; edge-on faces impose nothing. The centroid sort's violations are printed alongside.
#include "PsiCellCenterDepthSort.h"
#include "PsiMPVONCSort.h"
#include "PsiTestCheck.h"
#include "PsiTetConnectivity.h"
#include "vtkPsiConformingTetrahedralize.h"

#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
constexpr int FaceVerts[4][3] = { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 2 } };

struct Mesh
{
  std::vector<float> Points4;
  std::vector<uint32_t> Tets;
  std::vector<int32_t> Neighbors;
  size_t NumTets() const { return Tets.size() / 4; }
};

Mesh Tetrahedralize(int nx, int ny, int nz, int mode, const double origin[3])
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx, ny, nz);
  image->SetOrigin(origin[0], origin[1], origin[2]);
  image->SetSpacing(1.0, 0.75, 1.25);
  vtkNew<vtkPsiConformingTetrahedralize> filter;
  filter->SetSplitMode(mode);
  filter->SetInputData(image);
  filter->Update();
  vtkUnstructuredGrid* ug = filter->GetOutput();
  Mesh m;
  for (vtkIdType i = 0; i < ug->GetNumberOfPoints(); ++i)
  {
    double x[3];
    ug->GetPoint(i, x);
    m.Points4.insert(m.Points4.end(), { float(x[0]), float(x[1]), float(x[2]), 0.f });
  }
  for (vtkIdType t = 0; t < ug->GetNumberOfCells(); ++t)
  {
    vtkIdType n;
    const vtkIdType* p;
    ug->GetCells()->GetCellAtId(t, n, p);
    m.Tets.insert(m.Tets.end(), { uint32_t(p[0]), uint32_t(p[1]), uint32_t(p[2]), uint32_t(p[3]) });
  }
  psi::ComputeTetNeighbors(m.Tets.data(), m.NumTets(), 0, m.Neighbors);
  return m;
}

bool IsPermutation(const std::vector<uint32_t>& order, size_t n)
{
  if (order.size() != n)
    return false;
  std::vector<char> seen(n, 0);
  for (uint32_t t : order)
  {
    if (t >= n || seen[t])
      return false;
    seen[t] = 1;
  }
  return true;
}

// Violated adjacency constraints of `order`, decided independently: CGAL's exact orientation of
// the eye (perspective) against the face plane, or the sign of the normal along the view direction
// (parallel, in long double). Faces decided by the tetrahedron with the smaller id, as documented.
size_t Violations(const Mesh& m, const std::vector<uint32_t>& order, const double eye[3],
  bool parallel, size_t* constraints = nullptr)
{
  std::vector<size_t> pos(m.NumTets());
  for (size_t i = 0; i < order.size(); ++i)
    pos[order[i]] = i;
  auto P = [&](uint32_t id)
  { return Point3(m.Points4[4 * id], m.Points4[4 * id + 1], m.Points4[4 * id + 2]); };
  const Point3 E(eye[0], eye[1], eye[2]);
  size_t bad = 0, count = 0;
  for (size_t t = 0; t < m.NumTets(); ++t)
  {
    const uint32_t* v = &m.Tets[4 * t];
    for (int f = 0; f < 4; ++f)
    {
      const int32_t n = m.Neighbors[4 * t + f];
      if (n < 0 || size_t(n) <= t)
        continue;
      const Point3 a = P(v[FaceVerts[f][0]]), b = P(v[FaceVerts[f][1]]), c = P(v[FaceVerts[f][2]]);
      const int so = CGAL::orientation(a, b, c, P(v[f]));
      int se;
      if (parallel)
      {
        const long double u[3] = { (long double)b.x() - a.x(), (long double)b.y() - a.y(),
          (long double)b.z() - a.z() };
        const long double w[3] = { (long double)c.x() - a.x(), (long double)c.y() - a.y(),
          (long double)c.z() - a.z() };
        const long double N[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
          u[0] * w[1] - u[1] * w[0] };
        const long double s = -(N[0] * eye[0] + N[1] * eye[1] + N[2] * eye[2]);
        const long double scale = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
        se = std::abs(s) <= 1e-9L * scale ? 0 : (s > 0 ? 1 : -1);
      }
      else
      {
        se = CGAL::orientation(a, b, c, E);
      }
      if (so == 0 || se == 0)
        continue; // edge-on face: either order is right
      ++count;
      const bool neighborBehind = so == se;
      bad += neighborBehind ? pos[n] > pos[t] : pos[t] > pos[n];
    }
  }
  if (constraints)
    *constraints = count;
  return bad;
}

double Seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void TestConvex()
{
  std::mt19937 rng(17);
  std::normal_distribution<double> G(0, 1);
  const double origin[3] = { -3, -2, -4 };
  for (int mode : { 0, 1 })
  {
    const Mesh m = Tetrahedralize(9, 8, 7, mode, origin);
    const double center[3] = { origin[0] + 4, origin[1] + 3.5 * 0.75, origin[2] + 3 * 1.25 };
    size_t worstCentroid = 0, sumCentroid = 0, totalConstraints = 0, cycles = 0, bad = 0,
           badPerm = 0;
    size_t badNearest = 0;
    double sortTime = 0;
    for (int view = 0; view < 80; ++view)
    {
      const bool parallel = view % 2 == 1;
      double d[3] = { G(rng), G(rng), G(rng) };
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      double eye[3];
      for (int k = 0; k < 3; ++k)
      {
        d[k] /= len;
        // Perspective: an eye outside the box at a random distance; parallel: a direction.
        eye[k] = parallel ? d[k] : center[k] + (12 + 20 * (view % 5)) * d[k];
      }
      std::vector<uint32_t> order;
      const auto t0 = std::chrono::steady_clock::now();
      const psi::MPVONCResult r = psi::SortMPVONC(
        m.Points4.data(), m.Tets.data(), m.NumTets(), m.Neighbors.data(), eye, parallel, order);
      sortTime += Seconds(t0);
      badPerm += !IsPermutation(order, m.NumTets());
      size_t constraints = 0;
      bad += Violations(m, order, eye, parallel, &constraints);
      totalConstraints += constraints;
      cycles += r.CyclesBroken;
      // nearest first (front-to-back compositing): reversed, a back-to-front order as exact
      std::vector<uint32_t> nearest;
      cycles += psi::SortMPVONC(m.Points4.data(), m.Tets.data(), m.NumTets(), m.Neighbors.data(),
        eye, parallel, nearest, {}, psi::SortDirection::NearestFirst)
                  .CyclesBroken;
      std::reverse(nearest.begin(), nearest.end());
      badPerm += !IsPermutation(nearest, m.NumTets());
      badNearest += Violations(m, nearest, eye, parallel);
      std::vector<uint32_t> centroidOrder;
      psi::SortBackToFront(psi::ComputeCentroids(m.Points4.data(), m.Tets.data(), m.NumTets()), eye,
        parallel, centroidOrder);
      const size_t vc = Violations(m, centroidOrder, eye, parallel);
      worstCentroid = std::max(worstCentroid, vc);
      sumCentroid += vc;
    }
    PSI_CHECK(badPerm == 0, "%zu orders are not permutations", badPerm);
    PSI_CHECK(bad == 0, "mode %d: MPVONC violates %zu adjacency constraints", mode, bad);
    PSI_CHECK(
      badNearest == 0, "mode %d: nearest first, MPVONC violates %zu constraints", mode, badNearest);
    PSI_CHECK(cycles == 0, "mode %d: %zu cycles broken in a convex regular mesh", mode, cycles);
    PSI_CHECK(
      totalConstraints > 80 * m.NumTets(), "too few constraints checked: %zu", totalConstraints);
    std::printf("convex box (%s, %zu tets), 40 perspective + 40 parallel views: MPVONC violates "
                "%zu of %zu constraints (%.2f ms per sort); the centroid sort violates %zu "
                "(%.1f%%), at worst %zu in a view\n",
      mode ? "five per hex" : "conforming", m.NumTets(), bad, totalConstraints, 1e3 * sortTime / 80,
      sumCentroid, 100.0 * sumCentroid / totalConstraints, worstCentroid);
  }
}

void TestDisconnected()
{
  // Two boxes apart along x, seen along +-x (parallel) or from either side (perspective): every
  // tetrahedron of the far box must come before every one of the near box (the depth heuristic
  // between components, Williams §6).
  const double o1[3] = { 0, 0, 0 }, o2[3] = { 10, 0.3, -0.2 };
  Mesh a = Tetrahedralize(4, 4, 4, 0, o1);
  const Mesh b = Tetrahedralize(5, 3, 4, 0, o2);
  const uint32_t na = uint32_t(a.NumTets()), pa = uint32_t(a.Points4.size() / 4);
  a.Points4.insert(a.Points4.end(), b.Points4.begin(), b.Points4.end());
  for (uint32_t id : b.Tets)
    a.Tets.push_back(id + pa);
  for (int32_t n : b.Neighbors)
    a.Neighbors.push_back(n < 0 ? n : n + int32_t(na));
  struct View
  {
    double Eye[3];
    bool Parallel;
    bool AFar;
  };
  const View views[4] = { { { 1, 0.1, 0.05 }, true, false }, { { -1, 0.2, 0 }, true, true },
    { { -30, 1, 2 }, false, false }, { { 40, 2, -1 }, false, true } };
  for (const View& v : views)
    for (psi::SortDirection direction :
      { psi::SortDirection::FarthestFirst, psi::SortDirection::NearestFirst })
    {
      std::vector<uint32_t> order;
      const psi::MPVONCResult r = psi::SortMPVONC(a.Points4.data(), a.Tets.data(), a.NumTets(),
        a.Neighbors.data(), v.Eye, v.Parallel, order, {}, direction);
      if (direction == psi::SortDirection::NearestFirst)
      {
        std::reverse(order.begin(), order.end()); // reversed, the far component must come first
      }
      PSI_CHECK(IsPermutation(order, a.NumTets()), "not a permutation");
      // Position of the last far-box tetrahedron and the first near-box one.
      size_t lastFar = 0, firstNear = order.size();
      for (size_t i = 0; i < order.size(); ++i)
      {
        const bool inA = order[i] < na;
        if (inA == v.AFar)
          lastFar = i;
        else
          firstNear = std::min(firstNear, i);
      }
      PSI_CHECK(lastFar < firstNear, "components interleaved: last far at %zu, first near at %zu",
        lastFar, firstNear);
      PSI_CHECK(Violations(a, order, v.Eye, v.Parallel) == 0 && r.CyclesBroken == 0,
        "two boxes: violations or cycles");
    }
  std::printf("two disjoint boxes, 4 views, both directions: the far component always entirely "
              "first (last, nearest first)\n");
}

void TestDegenerateFaces()
{
  // The eye exactly in grid planes (x = 2, z = 0.5 + 1.25 k): many faces are seen edge-on.
  const double origin[3] = { 0, 0, 0.5 };
  const Mesh m = Tetrahedralize(6, 6, 6, 0, origin);
  const double eye[3] = { 2, -7, 0.5 + 1.25 * 2 };
  std::vector<uint32_t> order;
  const psi::MPVONCResult r = psi::SortMPVONC(
    m.Points4.data(), m.Tets.data(), m.NumTets(), m.Neighbors.data(), eye, false, order);
  PSI_CHECK(IsPermutation(order, m.NumTets()), "edge-on: not a permutation");
  PSI_CHECK(r.DegenerateFaces > 0, "edge-on: no degenerate face detected");
  PSI_CHECK(Violations(m, order, eye, false) == 0, "edge-on: constraints violated");
  // Parallel projection along an axis: every face parallel to it is edge-on.
  const double dir[3] = { 0, 1, 0 };
  const psi::MPVONCResult p = psi::SortMPVONC(
    m.Points4.data(), m.Tets.data(), m.NumTets(), m.Neighbors.data(), dir, true, order);
  PSI_CHECK(IsPermutation(order, m.NumTets()) && Violations(m, order, dir, true) == 0,
    "axis-parallel view: bad order");
  std::printf("eye in face planes: %zu edge-on faces (perspective), %zu (parallel along y); "
              "valid orders, %zu + %zu cycle breaks\n",
    r.DegenerateFaces, p.DegenerateFaces, r.CyclesBroken, p.CyclesBroken);
}

void TestCycles()
{
  // A constructed cycle (Williams §7) of three tetrahedra with declared (reciprocal) neighbours,
  // eye above them. Each tetrahedron has its base (face 0) at z = z0 facing the eye and its apex
  // below. t0's base is a front face: t0 is behind t1 there. t1's base: t1 is behind t2. t0's
  // face 3 (apex, v1, v2; plane y + z + 3 = 0) has the eye on t0's side: t2 is behind t0.
  // Hence t0 -> t1 -> t2 -> t0: one break needed, violating exactly one constraint.
  Mesh m;
  auto addTet = [&](float z, float apexDz, float shift)
  {
    const uint32_t base = uint32_t(m.Points4.size() / 4);
    const float p[4][3] = { { shift, 0, z + apexDz }, { shift - 1, -1, z }, { shift + 1, -1, z },
      { shift, 1, z } };
    for (const auto& q : p)
      m.Points4.insert(m.Points4.end(), { q[0], q[1], q[2], 0.f });
    m.Tets.insert(m.Tets.end(), { base, base + 1, base + 2, base + 3 });
  };
  addTet(-2, -1, 0);  // t0: base at z = -2 faces the eye (apex farther)
  addTet(-3, -1, 5);  // t1: base faces the eye
  addTet(-4, -1, -5); // t2
  m.Neighbors.assign(12, -1);
  m.Neighbors[4 * 0 + 0] = 1; // t0 face 0 = base (z = -2), a front face -> t0 behind t1
  m.Neighbors[4 * 1 + 1] = 0;
  m.Neighbors[4 * 1 + 0] = 2; // t1 face 0 = base, a front face -> t1 behind t2
  m.Neighbors[4 * 2 + 1] = 1;
  m.Neighbors[4 * 0 + 3] =
    2; // t0 face 3 = (apex, 1, 2): a back face seen from above -> t2 behind t0
  m.Neighbors[4 * 2 + 2] = 0;
  const double eye[3] = { 0, -0.5, 10 };
  std::vector<uint32_t> order;
  const psi::MPVONCResult r = psi::SortMPVONC(
    m.Points4.data(), m.Tets.data(), m.NumTets(), m.Neighbors.data(), eye, false, order);
  size_t constraints = 0;
  const size_t violated = Violations(m, order, eye, false, &constraints);
  PSI_CHECK(IsPermutation(order, 3), "cycle: not a permutation");
  PSI_CHECK(constraints == 3, "cycle: %zu constraints, expected 3", constraints);
  PSI_CHECK(r.CyclesBroken == 1, "cycle: %zu cycle breaks reported, expected 1", r.CyclesBroken);
  PSI_CHECK(violated == 1 && r.ViolatedConstraints == 1,
    "cycle: %zu violated (reported %zu), a 3-cycle must violate exactly 1", violated,
    r.ViolatedConstraints);
  std::printf("constructed 3-cycle: order %u %u %u, %zu cycle break, %zu violated constraint\n",
    order[0], order[1], order[2], r.CyclesBroken, r.ViolatedConstraints);

  // Random reciprocal neighbour graphs on random tetrahedra: cycles galore, always terminating.
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> U(-1, 1);
  size_t totalBreaks = 0;
  for (int trial = 0; trial < 20; ++trial)
  {
    Mesh g;
    const size_t n = 2000;
    for (size_t i = 0; i < 4 * n; ++i)
      g.Points4.insert(g.Points4.end(), { U(rng), U(rng), U(rng), 0.f });
    for (uint32_t i = 0; i < 4 * n; ++i)
      g.Tets.push_back(i);
    g.Neighbors.assign(4 * n, -1);
    std::vector<uint32_t> slots(4 * n);
    for (uint32_t i = 0; i < 4 * n; ++i)
      slots[i] = i;
    std::shuffle(slots.begin(), slots.end(), rng);
    for (size_t i = 0; i + 1 < slots.size(); i += 2)
    {
      const uint32_t a = slots[i], b = slots[i + 1];
      if (a / 4 == b / 4)
        continue;
      bool dup = false; // at most one face between two tetrahedra
      for (int f = 0; f < 4; ++f)
        dup |= g.Neighbors[4 * (a / 4) + f] == int32_t(b / 4);
      if (dup)
        continue;
      g.Neighbors[a] = int32_t(b / 4);
      g.Neighbors[b] = int32_t(a / 4);
    }
    const double e[3] = { U(rng) * 3.0, U(rng) * 3.0, 5.0 };
    std::vector<uint32_t> o;
    const psi::MPVONCResult gr =
      psi::SortMPVONC(g.Points4.data(), g.Tets.data(), n, g.Neighbors.data(), e, trial % 2, o);
    PSI_CHECK(IsPermutation(o, n), "random graph: not a permutation");
    const size_t v = Violations(g, o, e, trial % 2);
    PSI_CHECK(v == gr.ViolatedConstraints, "random graph: %zu violations, %zu reported", v,
      gr.ViolatedConstraints);
    PSI_CHECK(gr.CyclesBroken > 0, "random graph without cycles?");
    totalBreaks += gr.CyclesBroken;
  }
  std::printf("20 random cyclic graphs (2000 tets each): valid permutations, %zu cycle breaks, "
              "violations exactly as reported\n",
    totalBreaks);
}

void TestConnectivity()
{
  // Non-manifold faces: three tetrahedra on one triangle.
  const uint32_t tets[12] = { 0, 1, 2, 3, 0, 1, 2, 4, 5, 0, 1, 2 };
  std::vector<int32_t> nb;
  const psi::TetConnectivityResult r = psi::ComputeTetNeighbors(tets, 3, 0, nb);
  PSI_CHECK(r.NonManifoldFaces == 1 && r.InteriorFaces == 0 && r.BoundaryFaces == 9,
    "non-manifold: %zu non-manifold, %zu interior, %zu boundary", r.NonManifoldFaces,
    r.InteriorFaces, r.BoundaryFaces);
  PSI_CHECK(std::all_of(nb.begin(), nb.end(), [](int32_t v) { return v == -1; }),
    "non-manifold faces must be -1");

  // Timing on ~1M tetrahedra (55^3 cells x 6).
  const double origin[3] = { 0, 0, 0 };
  const Mesh m = Tetrahedralize(56, 56, 56, 0, origin);
  std::vector<int32_t> nb2;
  const auto t0 = std::chrono::steady_clock::now();
  const psi::TetConnectivityResult big =
    psi::ComputeTetNeighbors(m.Tets.data(), m.NumTets(), 0, nb2);
  const double s = Seconds(t0);
  // A closed 55^3-cell box: 4 n = 2 interior + boundary; boundary = 2 triangles per boundary quad.
  const size_t boundary = 2 * 2 * (3 * 55 * 55);
  PSI_CHECK(big.BoundaryFaces == boundary && 2 * big.InteriorFaces + boundary == 4 * m.NumTets() &&
      big.NonManifoldFaces == 0,
    "1M: %zu boundary (expected %zu), %zu interior", big.BoundaryFaces, boundary,
    big.InteriorFaces);
  PSI_CHECK(nb2 == m.Neighbors, "connectivity not deterministic");
  // In passes (4 of them above): the same as in one pass, and as in passes of one bucket each.
  std::vector<int32_t> onePass, tinyPasses;
  psi::ComputeTetNeighbors(m.Tets.data(), m.NumTets(), 0, onePass, 4 * m.NumTets());
  PSI_CHECK(nb2 == onePass, "connectivity in passes differs from one pass");
  const Mesh small = Tetrahedralize(9, 8, 7, 0, origin);
  std::vector<int32_t> smallOne;
  psi::ComputeTetNeighbors(small.Tets.data(), small.NumTets(), 0, smallOne, 4 * small.NumTets());
  psi::ComputeTetNeighbors(small.Tets.data(), small.NumTets(), 0, tinyPasses, 1);
  PSI_CHECK(tinyPasses == smallOne, "connectivity in one-bucket passes differs from one pass");
  std::printf("connectivity of %zu tets: %.3f s (%zu interior, %zu boundary faces)\n", m.NumTets(),
    s, big.InteriorFaces, big.BoundaryFaces);
}
} // namespace

int main()
{
  TestConnectivity();
  TestConvex();
  TestDisconnected();
  TestDegenerateFaces();
  TestCycles();
  return psitest::Report("TestMPVONC");
}
