// Tests of vtkPsiConformingTetrahedralize: tetrahedron counts on known grids, conformity
// (every interior triangle shared by exactly two tetrahedra; the unshared triangles tile exactly
// the domain's surface), exact positive orientation (CGAL), cell data to child tetrahedra, removal
// and count of degenerate tetrahedra, FaceNeighbors against a brute-force map, bad input.
// Usage: TestConformingTetrahedralize synthetic | bluntfin DATA_DIR | badinput DATA_DIR
// (the data modes exit with 77, "skipped", when DATA_DIR lacks the files).
#include "PsiBluntFin.h"
#include "PsiConformityCheck.h"
#include "PsiTestCheck.h"
#include "vtkPsiConformingTetrahedralize.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataSetReader.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRectilinearGrid.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace
{
using psitest::Check;
using psitest::ExpectConformingBox;
using psitest::MeshStats;
using psitest::Tet;

class Listener : public vtkCommand
{
public:
  static Listener* New() { return new Listener; }
  void Execute(vtkObject* caller, unsigned long event, void* data) override
  {
    if (event == vtkCommand::ProgressEvent)
    {
      this->LastProgress = *static_cast<double*>(data);
      if (this->AbortAt >= 0 && this->LastProgress >= this->AbortAt)
      {
        static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      }
      return;
    }
    ++(event == vtkCommand::WarningEvent ? this->Warnings : this->Errors);
    this->Last = data ? static_cast<const char*>(data) : "";
  }
  int Warnings = 0, Errors = 0;
  double LastProgress = -1, AbortAt = -1;
  std::string Last;
};

struct Run
{
  vtkNew<vtkPsiConformingTetrahedralize> Filter;
  vtkNew<Listener> Events;
  vtkUnstructuredGrid* Output = nullptr;
  double Seconds = 0;
  Run(vtkDataObject* input, int mode, double abortAt = -1)
  {
    this->Filter->SetSplitMode(mode);
    this->Filter->SetInputData(input);
    this->Filter->AddObserver(vtkCommand::WarningEvent, this->Events);
    this->Filter->AddObserver(vtkCommand::ErrorEvent, this->Events);
    this->Filter->AddObserver(vtkCommand::ProgressEvent, this->Events);
    this->Events->AbortAt = abortAt;
    const auto t0 = std::chrono::steady_clock::now();
    this->Filter->Update();
    this->Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    this->Output = this->Filter->GetOutput();
  }
};

vtkSmartPointer<vtkImageData> MakeImage(int nx, int ny, int nz)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(0.5, 0.25, 1.0);
  image->SetOrigin(-1, 2, 0.5);
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("CellId");
  cellIds->SetNumberOfTuples(image->GetNumberOfCells());
  std::iota(cellIds->GetPointer(0), cellIds->GetPointer(0) + image->GetNumberOfCells(), 0);
  image->GetCellData()->AddArray(cellIds);
  vtkNew<vtkDoubleArray> value;
  value->SetName("PointValue");
  value->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    value->SetValue(i, x[0] + 2 * x[1] + 3 * x[2]);
  }
  image->GetPointData()->AddArray(value);
  return image;
}

void TestCountsAndAttributes()
{
  auto image = MakeImage(5, 4, 6); // 4 x 3 x 5 = 60 cells
  const vtkIdType cells = image->GetNumberOfCells();
  double bounds[6];
  image->GetBounds(bounds);
  for (int mode : { 0, 1 })
  {
    Run r(image, mode);
    const vtkIdType per = mode == 0 ? 6 : 5;
    PSI_CHECK(r.Output->GetNumberOfCells() == per * cells,
      "image mode %d: %lld tets, expected %lld", mode, (long long)r.Output->GetNumberOfCells(),
      (long long)(per * cells));
    PSI_CHECK(r.Filter->GetNumberOfGeneratedTets() == per * cells, "generated %lld",
      (long long)r.Filter->GetNumberOfGeneratedTets());
    PSI_CHECK(r.Filter->GetNumberOfRemovedDegenerateTets() == 0, "removed %lld on a regular grid",
      (long long)r.Filter->GetNumberOfRemovedDegenerateTets());
    PSI_CHECK(r.Events->LastProgress == 1.0, "progress ended at %g", r.Events->LastProgress);
    ExpectConformingBox(
      mode ? "image 4x3x5, five per hex" : "image 4x3x5, conforming", r.Output, bounds);

    // Cell data: every child's centroid lies inside its parent cell; point data unchanged.
    auto* ids = vtkIntArray::SafeDownCast(r.Output->GetCellData()->GetArray("CellId"));
    PSI_CHECK(ids != nullptr, "CellId not copied");
    vtkIdType outside = 0;
    std::vector<int> children(cells, 0);
    for (vtkIdType t = 0; ids && t < r.Output->GetNumberOfCells(); ++t)
    {
      const auto v = Tet(r.Output, t);
      double c[3] = { 0, 0, 0 }, x[3], cb[6];
      for (vtkIdType p : v)
      {
        r.Output->GetPoint(p, x);
        for (int k = 0; k < 3; ++k)
          c[k] += 0.25 * x[k];
      }
      const int parent = ids->GetValue(t);
      ++children[parent];
      image->GetCellBounds(parent, cb);
      for (int k = 0; k < 3; ++k)
        outside += c[k] <= cb[2 * k] || c[k] >= cb[2 * k + 1];
    }
    PSI_CHECK(outside == 0, "%lld child centroids outside their parent cell", (long long)outside);
    PSI_CHECK(std::all_of(children.begin(), children.end(), [&](int k) { return k == per; }),
      "a cell does not have %lld children", (long long)per);
    auto* in = image->GetPointData()->GetArray("PointValue");
    auto* out = r.Output->GetPointData()->GetArray("PointValue");
    PSI_CHECK(out && out->GetNumberOfTuples() == in->GetNumberOfTuples(), "point data not passed");
    double worst = 0;
    for (vtkIdType i = 0; out && i < in->GetNumberOfTuples(); ++i)
      worst = std::max(worst, std::abs(in->GetTuple1(i) - out->GetTuple1(i)));
    PSI_CHECK(worst == 0, "point data changed by %g", worst);
  }

  // The same grid as rectilinear and structured input: same counts.
  vtkNew<vtkRectilinearGrid> rg;
  rg->SetDimensions(4, 3, 5);
  vtkNew<vtkDoubleArray> xc, yc, zc;
  for (double v : { 0.0, 0.3, 1.0, 1.1 })
    xc->InsertNextValue(v);
  for (double v : { 0.0, 2.0, 2.5 })
    yc->InsertNextValue(v);
  for (double v : { -1.0, 0.0, 0.1, 0.7, 3.0 })
    zc->InsertNextValue(v);
  rg->SetXCoordinates(xc);
  rg->SetYCoordinates(yc);
  rg->SetZCoordinates(zc);
  rg->GetBounds(bounds);
  for (int mode : { 0, 1 })
  {
    Run r(rg, mode);
    PSI_CHECK(r.Output->GetNumberOfCells() == (mode ? 5 : 6) * rg->GetNumberOfCells(),
      "rectilinear mode %d: %lld tets", mode, (long long)r.Output->GetNumberOfCells());
    ExpectConformingBox(
      mode ? "rectilinear, five per hex" : "rectilinear, conforming", r.Output, bounds);
  }
}

// Hexahedra, wedges, pyramids (around an added centre point), tetrahedra and polyhedra filling a
// box, with the point ids shuffled so that every min-id configuration occurs.
vtkSmartPointer<vtkUnstructuredGrid> MakeMixed(int n, bool degenerateHexes = false)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> J(-0.12, 0.12);
  std::vector<std::array<double, 3>> pts;
  auto gid = [&](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
      {
        std::array<double, 3> x = { double(i), double(j), double(k) };
        const int idx[3] = { i, j, k };
        for (int a = 0; a < 3; ++a)
          if (idx[a] > 0 && idx[a] < n)
            x[a] += J(rng); // interior coordinates jittered: the box surface stays planar
        pts.push_back(x);
      }
  struct Cell
  {
    int Type;
    std::vector<vtkIdType> Ids;
  };
  std::vector<Cell> cells;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType h[8] = { gid(i, j, k), gid(i + 1, j, k), gid(i + 1, j + 1, k),
          gid(i, j + 1, k), gid(i, j, k + 1), gid(i + 1, j, k + 1), gid(i + 1, j + 1, k + 1),
          gid(i, j + 1, k + 1) };
        // Wedges fill whole columns (their triangles are stacked, the ends on the boundary).
        int region = (i + 2 * j) % 5 == 1 ? 1 : (i + 2 * j + 3 * k) % 5;
        region = region == 1 && (i + 2 * j) % 5 != 1 ? 0 : region;
        if (region == 0 || degenerateHexes)
        {
          cells.push_back({ VTK_HEXAHEDRON, { h, h + 8 } });
        }
        else if (region == 1) // two wedges: the bottom and top quads split the same way
        {
          cells.push_back({ VTK_WEDGE, { h[0], h[1], h[2], h[4], h[5], h[6] } });
          cells.push_back({ VTK_WEDGE, { h[0], h[2], h[3], h[4], h[6], h[7] } });
        }
        else if (region == 2 || region == 3) // six pyramids on the faces, apex at the centre
        {
          std::array<double, 3> c = { 0, 0, 0 };
          for (vtkIdType p : h)
            for (int a = 0; a < 3; ++a)
              c[a] += pts[p][a] / 8;
          const vtkIdType apex = static_cast<vtkIdType>(pts.size());
          pts.push_back(c);
          const int quads[6][4] = { { 0, 1, 2, 3 }, { 4, 7, 6, 5 }, { 0, 4, 5, 1 }, { 1, 5, 6, 2 },
            { 2, 6, 7, 3 }, { 3, 7, 4, 0 } };
          for (const auto& q : quads)
          {
            // Faces on the box boundary (region 3 only): two tetrahedra instead of the pyramid.
            bool onBoundary = false;
            for (int a = 0; a < 3; ++a)
            {
              const double x0 = pts[h[q[0]]][a];
              bool same = x0 == 0 || x0 == n;
              for (int m = 1; m < 4; ++m)
                same = same && pts[h[q[m]]][a] == x0;
              onBoundary = onBoundary || same;
            }
            if (region == 3 && onBoundary)
            {
              cells.push_back({ VTK_TETRA, { h[q[0]], h[q[1]], h[q[2]], apex } });
              cells.push_back({ VTK_TETRA, { h[q[0]], h[q[2]], h[q[3]], apex } });
            }
            else
            {
              cells.push_back({ VTK_PYRAMID, { h[q[0]], h[q[1]], h[q[2]], h[q[3]], apex } });
            }
          }
        }
        else // the hexahedron as a VTK_POLYHEDRON face stream
        {
          const int quads[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 },
            { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };
          Cell c{ VTK_POLYHEDRON, { 6 } };
          for (const auto& q : quads)
          {
            c.Ids.push_back(4);
            for (int m : q)
              c.Ids.push_back(h[m]);
          }
          cells.push_back(c);
        }
      }
  // Shuffle the point ids.
  std::vector<vtkIdType> perm(pts.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(pts.size()));
  for (size_t p = 0; p < pts.size(); ++p)
    points->SetPoint(perm[p], pts[p].data());
  ug->SetPoints(points);
  ug->Allocate(static_cast<vtkIdType>(cells.size()));
  for (auto& c : cells)
  {
    if (c.Type == VTK_POLYHEDRON)
    {
      std::vector<vtkIdType> stream = c.Ids, unique;
      for (size_t m = 1; m < stream.size();)
      {
        const vtkIdType np = stream[m++];
        for (vtkIdType q = 0; q < np; ++q, ++m)
        {
          stream[m] = perm[stream[m]];
          unique.push_back(stream[m]);
        }
      }
      std::sort(unique.begin(), unique.end());
      unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
      ug->InsertNextCell(VTK_POLYHEDRON, static_cast<vtkIdType>(unique.size()), unique.data(),
        stream[0], stream.data() + 1);
    }
    else
    {
      for (auto& id : c.Ids)
        id = perm[id];
      ug->InsertNextCell(c.Type, static_cast<vtkIdType>(c.Ids.size()), c.Ids.data());
    }
  }
  return ug;
}

void TestMixed()
{
  auto ug = MakeMixed(5);
  int count[VTK_NUMBER_OF_CELL_TYPES] = {};
  for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c)
    ++count[ug->GetCellType(c)];
  const double bounds[6] = { 0, 5, 0, 5, 0, 5 };
  Run r(ug, 0);
  std::printf("mixed input: %d hexahedra, %d wedges, %d pyramids, %d tetrahedra, %d polyhedra\n",
    count[VTK_HEXAHEDRON], count[VTK_WEDGE], count[VTK_PYRAMID], count[VTK_TETRA],
    count[VTK_POLYHEDRON]);
  PSI_CHECK(count[VTK_HEXAHEDRON] && count[VTK_WEDGE] && count[VTK_PYRAMID] && count[VTK_TETRA] &&
      count[VTK_POLYHEDRON],
    "the mixed mesh lacks a cell type");
  const vtkIdType expected = 6 * (count[VTK_HEXAHEDRON] + count[VTK_POLYHEDRON]) +
    3 * count[VTK_WEDGE] + 2 * count[VTK_PYRAMID] + count[VTK_TETRA];
  PSI_CHECK(r.Output->GetNumberOfCells() == expected, "mixed: %lld tets, expected %lld",
    (long long)r.Output->GetNumberOfCells(), (long long)expected);
  ExpectConformingBox("mixed, shuffled ids, conforming", r.Output, bounds);

  // Hexahedra only, shuffled ids: 6 per hexahedron whatever the min-id configuration.
  auto hexes = MakeMixed(6, true);
  Run h(hexes, 0);
  PSI_CHECK(h.Output->GetNumberOfCells() == 6 * hexes->GetNumberOfCells(), "hexes: %lld tets",
    (long long)h.Output->GetNumberOfCells());
  const double b6[6] = { 0, 6, 0, 6, 0, 6 };
  ExpectConformingBox("hexahedra, shuffled ids", h.Output, b6);

  // 'Five per hex' on unstructured input falls back to the conforming split, with a warning.
  Run f(hexes, 1);
  PSI_CHECK(f.Filter->GetFellBackToConforming() && f.Events->Warnings > 0,
    "no fallback warning for five-per-hex on unstructured input");
  PSI_CHECK(f.Output->GetNumberOfCells() == h.Output->GetNumberOfCells(), "fallback count %lld",
    (long long)f.Output->GetNumberOfCells());
}

void TestDegenerate()
{
  // Two unit hexahedra side by side; the right one has its right face collapsed onto a segment
  // (two collapsed grid edges, as at the Blunt Fin's axis): a wedge of volume 1/2.
  vtkNew<vtkStructuredGrid> sg;
  sg->SetDimensions(3, 2, 2);
  vtkNew<vtkPoints> p;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        p->InsertNextPoint(i, i == 2 ? 0.5 : j, k);
  sg->SetPoints(p);
  for (int mode : { 0, 1 })
  {
    Run r(sg, mode);
    const vtkIdType gen = r.Filter->GetNumberOfGeneratedTets();
    const vtkIdType removed = r.Filter->GetNumberOfRemovedDegenerateTets();
    PSI_CHECK(gen == (mode ? 10 : 12), "collapsed: %lld generated", (long long)gen);
    PSI_CHECK(removed > 0, "collapsed: no degenerate tetrahedron removed");
    PSI_CHECK(r.Output->GetNumberOfCells() + removed == gen, "collapsed: %lld + %lld != %lld",
      (long long)r.Output->GetNumberOfCells(), (long long)removed, (long long)gen);
    auto* fd =
      vtkIdTypeArray::SafeDownCast(r.Output->GetFieldData()->GetArray("RemovedDegenerateTets"));
    PSI_CHECK(fd && fd->GetValue(0) == removed, "field-data count missing or wrong");
    const MeshStats s = Check(r.Output);
    PSI_CHECK(s.NonPositive == 0 && s.OverShared == 0, "collapsed: %lld non-positive, %lld over",
      (long long)s.NonPositive, (long long)s.OverShared);
    PSI_CHECK(std::abs(s.Volume - 1.5) < 1e-12, "collapsed: volume %.15g, expected 1.5", s.Volume);
    std::printf("collapsed hex (%s): %lld generated, %lld degenerate removed, volume %.15g\n",
      mode ? "five" : "conforming", (long long)gen, (long long)removed, s.Volume);
  }

  // A flat hexahedron (all z = 0): every tetrahedron is degenerate -> empty output, a warning.
  vtkNew<vtkUnstructuredGrid> flat;
  vtkNew<vtkPoints> fp;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        fp->InsertNextPoint(i, j, 0);
  flat->SetPoints(fp);
  const vtkIdType hex[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
  flat->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  Run r(flat, 0);
  PSI_CHECK(r.Output->GetNumberOfCells() == 0 && r.Filter->GetNumberOfRemovedDegenerateTets() == 6,
    "flat hex: %lld tets left, %lld removed", (long long)r.Output->GetNumberOfCells(),
    (long long)r.Filter->GetNumberOfRemovedDegenerateTets());
  PSI_CHECK(r.Events->Warnings > 0, "flat hex: no warning");
}

void TestEmptyAndAbort()
{
  vtkNew<vtkUnstructuredGrid> empty;
  Run r(empty, 0);
  PSI_CHECK(r.Output->GetNumberOfCells() == 0 && r.Output->GetNumberOfPoints() == 0,
    "empty input gave %lld cells", (long long)r.Output->GetNumberOfCells());
  PSI_CHECK(r.Events->Warnings == 1, "empty input: %d warnings", r.Events->Warnings);
  std::printf("empty grid: empty output, warning \"%s\"\n", r.Events->Last.c_str());

  auto image = MakeImage(30, 30, 30);
  Run a(image, 0, 0.3);
  PSI_CHECK(a.Output->GetNumberOfCells() == 0, "aborted run kept %lld cells",
    (long long)a.Output->GetNumberOfCells());
  std::printf("abort at progress 0.3: empty output, no crash\n");
}

bool HaveFiles(const std::string& dir, std::initializer_list<const char*> names)
{
  for (const char* n : names)
  {
    if (!std::ifstream(dir + "/" + n).good())
    {
      std::printf("SKIPPED: %s/%s not found (the shared data folder is absent)\n", dir.c_str(), n);
      return false;
    }
  }
  return true;
}

int TestBluntFin(const std::string& dir)
{
  if (!HaveFiles(dir, { "bluntfinxyz.bin", "bluntfinq.bin" }))
    return 77;
  vtkSmartPointer<vtkStructuredGrid> grid = psitest::ReadBluntFin(dir);
  PSI_CHECK(grid != nullptr, "no structured grid read");
  if (!grid)
    return 1;
  int dims[3];
  grid->GetDimensions(dims);
  const vtkIdType hexes = grid->GetNumberOfCells();
  std::printf(
    "Blunt Fin: %dx%dx%d points, %lld hexahedra\n", dims[0], dims[1], dims[2], (long long)hexes);
  PSI_CHECK(hexes == 37479, "Blunt Fin hexahedra %lld (MANIFEST: 37,479)", (long long)hexes);
  for (int mode : { 1, 0 })
  {
    Run r(grid, mode);
    const vtkIdType gen = r.Filter->GetNumberOfGeneratedTets();
    const vtkIdType removed = r.Filter->GetNumberOfRemovedDegenerateTets();
    PSI_CHECK(gen == (mode ? 5 : 6) * hexes, "mode %d: %lld generated", mode, (long long)gen);
    if (mode == 1)
      PSI_CHECK(gen == 187395, "five per hex: %lld tets before removal, the literature's 187,395",
        (long long)gen);
    PSI_CHECK(r.Output->GetNumberOfCells() + removed == gen, "count mismatch");
    const MeshStats s = Check(r.Output);
    PSI_CHECK(s.NonPositive == 0 && s.OverShared == 0 && s.NeighborMismatches == 0,
      "Blunt Fin: %lld non-positive, %lld over-shared, %lld neighbour mismatches",
      (long long)s.NonPositive, (long long)s.OverShared, (long long)s.NeighborMismatches);
    PSI_CHECK(r.Output->GetPointData()->GetArray("Density") != nullptr, "Density not passed");
    std::printf("Blunt Fin %-10s: %lld tets before removal, %lld degenerate removed, %lld left, "
                "%lld boundary triangles, volume %.6g, filter %.3f s\n",
      mode ? "five" : "conforming", (long long)gen, (long long)removed,
      (long long)r.Output->GetNumberOfCells(), (long long)s.BoundaryTriangles, s.Volume, r.Seconds);
  }
  return psitest::Failures() ? 1 : 0;
}

int TestBadInput(const std::string& dir)
{
  if (!HaveFiles(dir, { "blow.vtk" }))
    return 77;
  vtkNew<vtkDataSetReader> reader;
  reader->SetFileName((dir + "/blow.vtk").c_str());
  reader->Update();
  vtkDataSet* ds = reader->GetOutput();
  PSI_CHECK(ds && ds->GetNumberOfCells() > 0, "blow.vtk not read");
  if (!ds)
    return 1;
  Run r(ds, 0);
  PSI_CHECK(r.Output->GetNumberOfCells() == 0, "surface input gave %lld cells",
    (long long)r.Output->GetNumberOfCells());
  PSI_CHECK(r.Events->Warnings > 0 && r.Events->Errors == 0, "%d warnings, %d errors",
    r.Events->Warnings, r.Events->Errors);
  std::printf("blow.vtk (%lld surface cells): empty output, warning \"%s\"\n",
    (long long)ds->GetNumberOfCells(), r.Events->Last.c_str());
  return psitest::Failures() ? 1 : 0;
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string mode = argc > 1 ? argv[1] : "synthetic";
  const std::string dir = argc > 2 ? argv[2] : "";
  int rc = 0;
  if (mode == "bluntfin")
    rc = TestBluntFin(dir);
  else if (mode == "badinput")
    rc = TestBadInput(dir);
  else
  {
    TestCountsAndAttributes();
    TestMixed();
    TestDegenerate();
    TestEmptyAndAbort();
    rc = psitest::Failures() ? 1 : 0;
  }
  if (rc != 77)
    std::printf(
      "%s\n", rc ? "TestConformingTetrahedralize FAILED" : "TestConformingTetrahedralize passed");
  return rc;
}
