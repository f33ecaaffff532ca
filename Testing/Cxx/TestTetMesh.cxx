// The mesh as the renderer gathers it (psi::GatherTetMesh) and the reuse of the conforming
// filter's FaceNeighbors array by MPVONC (psi::FaceNeighborsFromArray, psi::FaceNeighborsMatch):
//  - the filter's neighbours equal those computed from the gathered mesh;
//  - cells skipped by the renderer (a non-tetrahedron, a NaN scalar) are remapped, and the
//    remapped neighbours equal those computed from the reduced mesh;
//  - with cell scalars (private points per tetrahedron) the filter's neighbours still match by
//    position, where connectivity by point id finds none;
//  - a stale array (cells reordered downstream) is rejected;
//  - the sort interface gives a permutation either way;
//  - a new time step replaces the scalars only, as gathering the mesh again would;
//  - a point no cell uses, near or far, changes neither the mesh's shift nor its bounds.
#include "PsiCellPointBounds.h"
#include "PsiTestCheck.h"
#include "PsiTetConnectivity.h"
#include "PsiTetMesh.h"
#include "PsiTransferFunctionAnalysis.h"
#include "PsiVisibilitySort.h"
#include "vtkPsiConformingTetrahedralize.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> Tetrahedralized(int n)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n + 1, n);
  image->SetSpacing(1.0, 0.75, 1.25);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    s->InsertNextValue(x[0] + 2 * x[1] - x[2]);
  }
  image->GetPointData()->SetScalars(s);
  vtkNew<vtkPsiConformingTetrahedralize> filter;
  filter->SetInputData(image);
  filter->Update();
  vtkSmartPointer<vtkUnstructuredGrid> out = filter->GetOutput();
  vtkNew<vtkDoubleArray> cs;
  cs->SetName("c");
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    cs->InsertNextValue(double(c % 7));
  }
  out->GetCellData()->AddArray(cs);
  return out;
}

std::vector<int32_t> Computed(const psi::TetMesh& m)
{
  std::vector<int32_t> nb;
  psi::ComputeTetNeighbors(m.Cells(), m.NumberOfTets(), m.NumberOfPoints(), nb);
  return nb;
}

// The four point ids of every tetrahedron, wherever the mesh keeps them.
std::vector<uint32_t> CellIds(const psi::TetMesh& m)
{
  std::vector<uint32_t> ids(4 * m.NumberOfTets());
  for (size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    m.Cells().Get(t, &ids[4 * t]);
  }
  return ids;
}

// The input's connectivity, cell by cell.
std::vector<uint32_t> InputIds(vtkUnstructuredGrid* ug)
{
  std::vector<uint32_t> ids;
  vtkNew<vtkIdList> pts;
  for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c)
  {
    ug->GetCellPoints(c, pts);
    for (vtkIdType k = 0; k < pts->GetNumberOfIds(); ++k)
    {
      ids.push_back(static_cast<uint32_t>(pts->GetId(k)));
    }
  }
  return ids;
}

// A mesh of tetrahedra with point data reads its cells from the input's connectivity (64- or
// 32-bit storage) instead of copying them; one with a cell to skip keeps its own copy.
void TestBorrowedCells()
{
  auto ug = Tetrahedralized(4);
  vtkDataArray* s = ug->GetPointData()->GetArray("s");
  const psi::TetMesh m = psi::GatherTetMesh(ug, s, false);
  PSI_CHECK(m.Borrowed && m.Tets.empty(), "tetrahedra with point data: cells borrowed");
  PSI_CHECK(
    m.NumberOfTets() == static_cast<size_t>(ug->GetNumberOfCells()) && CellIds(m) == InputIds(ug),
    "borrowed cells are the input's");
  vtkNew<vtkUnstructuredGrid> narrow;
  narrow->DeepCopy(ug);
  narrow->GetCells()->ConvertTo32BitStorage();
  const psi::TetMesh m32 = psi::GatherTetMesh(narrow, narrow->GetPointData()->GetArray("s"), false);
  PSI_CHECK(m32.Borrowed && CellIds(m32) == InputIds(ug), "32-bit connectivity borrowed too");
  PSI_CHECK(m32.ScalarRange[0] == m.ScalarRange[0] && m32.ScalarRange[1] == m.ScalarRange[1] &&
      m32.MaxEdgeLength == m.MaxEdgeLength && m32.MinEdgeLength == m.MinEdgeLength,
    "same measures from either storage");
  vtkNew<vtkDoubleArray> holed;
  holed->DeepCopy(s);
  holed->SetComponent(17, 0, std::numeric_limits<double>::quiet_NaN());
  const psi::TetMesh nan = psi::GatherTetMesh(ug, holed, false);
  PSI_CHECK(!nan.Borrowed && nan.NonFiniteTets > 0 &&
      nan.NumberOfTets() + nan.NonFiniteTets == static_cast<size_t>(ug->GetNumberOfCells()),
    "a NaN scalar: its tetrahedra skipped, the rest copied");
  const std::vector<uint32_t> ids = CellIds(m); // before the input changes below
  const psi::TetMesh copied = psi::GatherTetMesh(ug, ug->GetCellData()->GetArray("c"), true);
  PSI_CHECK(!copied.Borrowed && copied.Tets.size() == 4 * copied.NumberOfTets(),
    "cell scalars: private points, cells copied");
  const vtkIdType tri[3] = { 0, 1, 2 };
  ug->InsertNextCell(VTK_TRIANGLE, 3, tri);
  const psi::TetMesh mixed = psi::GatherTetMesh(ug, s, false);
  PSI_CHECK(!mixed.Borrowed && mixed.NumberOfTets() == ids.size() / 4 && CellIds(mixed) == ids,
    "a cell to skip: cells copied, the same tetrahedra");
}

bool Sorts(const psi::TetMesh& m, std::vector<int32_t> nb)
{
  auto sort = psi::NewMPVONCSort();
  sort->SetMesh(&m, std::move(nb));
  std::vector<uint32_t> order;
  const double eye[3] = { 30, 20, 10 };
  sort->Sort(eye, false, order);
  std::vector<uint32_t> sorted(order);
  std::sort(sorted.begin(), sorted.end());
  std::vector<uint32_t> ids(m.NumberOfTets());
  std::iota(ids.begin(), ids.end(), 0u);
  return sorted == ids;
}

void TestFilterNeighbors()
{
  auto ug = Tetrahedralized(5);
  vtkDataArray* fn = ug->GetCellData()->GetArray("FaceNeighbors");
  PSI_CHECK(fn != nullptr, "the filter writes FaceNeighbors");
  const psi::TetMesh m = psi::GatherTetMesh(ug, ug->GetPointData()->GetArray("s"), false);
  std::vector<int32_t> nb;
  PSI_CHECK(psi::FaceNeighborsFromArray(m, fn, ug->GetNumberOfCells(), nb), "array taken");
  PSI_CHECK(m.SourceCells.empty(), "no cell skipped");
  PSI_CHECK(nb == Computed(m), "filter neighbours equal computed ones");
  PSI_CHECK(psi::FaceNeighborsMatch(m, nb), "filter neighbours match the mesh");
  PSI_CHECK(Sorts(m, nb), "MPVONC with the filter's neighbours: a permutation");
}

void TestSkippedCells()
{
  auto ug = Tetrahedralized(5);
  const vtkIdType nc = ug->GetNumberOfCells();
  // a NaN at one point skips every tetrahedron around it; a triangle appended is skipped too
  vtkDataArray* s = ug->GetPointData()->GetArray("s");
  s->SetComponent(17, 0, std::numeric_limits<double>::quiet_NaN());
  const vtkIdType tri[3] = { 0, 1, 2 };
  vtkDataArray* fn = ug->GetCellData()->GetArray("FaceNeighbors");
  ug->InsertNextCell(VTK_TRIANGLE, 3, tri);
  const double none[4] = { -1, -1, -1, -1 };
  fn->InsertNextTuple(none);
  ug->GetCellData()->GetArray("c")->InsertNextTuple1(0);
  const psi::TetMesh m = psi::GatherTetMesh(ug, s, false);
  PSI_CHECK(m.NonTetCells == 1 && m.NonFiniteTets > 0, "skipped %lld + %lld",
    static_cast<long long>(m.NonTetCells), static_cast<long long>(m.NonFiniteTets));
  PSI_CHECK(m.SourceCells.size() == m.NumberOfTets() &&
      m.NumberOfTets() + m.NonFiniteTets == static_cast<size_t>(nc),
    "source cells recorded");
  std::vector<int32_t> nb;
  PSI_CHECK(psi::FaceNeighborsFromArray(m, fn, ug->GetNumberOfCells(), nb), "array taken");
  PSI_CHECK(nb == Computed(m), "remapped neighbours equal those of the reduced mesh");
  PSI_CHECK(Sorts(m, nb), "MPVONC after skipping: a permutation");
}

void TestCellScalars()
{
  auto ug = Tetrahedralized(4);
  const psi::TetMesh m = psi::GatherTetMesh(ug, ug->GetCellData()->GetArray("c"), true);
  PSI_CHECK(m.NumberOfPoints() == 4 * m.NumberOfTets(), "private points per tetrahedron");
  const std::vector<int32_t> byId = Computed(m);
  PSI_CHECK(std::count(byId.begin(), byId.end(), -1) == static_cast<long>(byId.size()),
    "connectivity by point id finds no neighbour with private points");
  std::vector<int32_t> nb;
  psi::FaceNeighborsFromArray(
    m, ug->GetCellData()->GetArray("FaceNeighbors"), ug->GetNumberOfCells(), nb);
  PSI_CHECK(psi::FaceNeighborsMatch(m, nb) &&
      std::count(nb.begin(), nb.end(), -1) < static_cast<long>(nb.size()) / 2,
    "the filter's neighbours match by position");
}

void TestStaleArray()
{
  auto ug = Tetrahedralized(4);
  const psi::TetMesh m = psi::GatherTetMesh(ug, ug->GetPointData()->GetArray("s"), false);
  std::vector<int32_t> nb;
  psi::FaceNeighborsFromArray(
    m, ug->GetCellData()->GetArray("FaceNeighbors"), ug->GetNumberOfCells(), nb);
  // as if a downstream filter had reordered the cells but passed the array through
  for (size_t t = 0; t + 1 < m.NumberOfTets(); t += 2)
  {
    for (int f = 0; f < 4; ++f)
    {
      std::swap(nb[4 * t + f], nb[4 * (t + 1) + f]);
    }
  }
  PSI_CHECK(!psi::FaceNeighborsMatch(m, nb), "a stale array is rejected");
  PSI_CHECK(Sorts(m, nb), "MPVONC falls back to computed neighbours");
  vtkNew<vtkIntArray> wrong;
  wrong->SetNumberOfComponents(3);
  wrong->SetNumberOfTuples(ug->GetNumberOfCells());
  PSI_CHECK(!psi::FaceNeighborsFromArray(m, wrong, ug->GetNumberOfCells(), nb) && nb.empty(),
    "an array of the wrong shape is not taken");
}
// A new time step on the same mesh: only the scalars change, and the result equals gathering
// the mesh again; cases that change which tetrahedra are drawn refuse.
void TestTimeStep()
{
  auto ug = Tetrahedralized(4);
  vtkDataArray* s = ug->GetPointData()->GetArray("s");
  psi::TetMesh m = psi::GatherTetMesh(ug, s, false);
  vtkNew<vtkDoubleArray> next;
  next->SetNumberOfTuples(s->GetNumberOfTuples());
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    next->SetValue(i, 3.0 * s->GetComponent(i, 0) + 1.0);
  }
  const std::vector<uint32_t> tets = CellIds(m);
  PSI_CHECK(psi::UpdateTetMeshScalars(m, next), "scalars replaced");
  const psi::TetMesh fresh = psi::GatherTetMesh(ug, next, false);
  PSI_CHECK(m.Points4 == fresh.Points4 && CellIds(m) == tets &&
      m.ScalarRange[0] == fresh.ScalarRange[0] && m.ScalarRange[1] == fresh.ScalarRange[1] &&
      m.MaxEdgeLength == fresh.MaxEdgeLength,
    "a time step equals the mesh gathered again");
  next->SetValue(5, std::numeric_limits<double>::infinity());
  const std::vector<float> before = m.Points4;
  PSI_CHECK(!psi::UpdateTetMeshScalars(m, next) && m.Points4 == before,
    "a non-finite scalar needs the mesh gathered again (and leaves it unchanged)");
  psi::TetMesh cells = psi::GatherTetMesh(ug, ug->GetCellData()->GetArray("c"), true);
  PSI_CHECK(!psi::UpdateTetMeshScalars(cells, ug->GetCellData()->GetArray("c")),
    "a mesh of cell scalars is gathered again");
}
// Coloring by a vector array follows the color map's vector mode: its magnitude, or the
// component it selects, as ParaView's 'Volume' maps it.
void TestVectorComponents()
{
  auto ug = Tetrahedralized(3);
  vtkNew<vtkDoubleArray> v;
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(ug->GetNumberOfPoints());
  for (vtkIdType i = 0; i < ug->GetNumberOfPoints(); ++i)
  {
    double x[3];
    ug->GetPoint(i, x);
    v->SetTuple3(i, x[0] + 1, -2 * x[1], 0.5 * x[2] + 3);
  }
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> ctf;
  property->SetColor(ctf);
  ctf->SetVectorModeToMagnitude();
  psi::ScalarComponent mag = psi::ColorMapComponent(property, 3);
  ctf->SetVectorModeToComponent();
  ctf->SetVectorComponent(2);
  psi::ScalarComponent z = psi::ColorMapComponent(property, 3);
  PSI_CHECK(mag.Index == psi::ScalarComponent::Magnitude && z.Index == 2 &&
      psi::ColorMapComponent(property, 1).Index == 0,
    "vector mode read from the color map (%d, %d)", mag.Index, z.Index);
  const psi::TetMesh mm = psi::GatherTetMesh(ug, v, false, mag);
  const psi::TetMesh mz = psi::GatherTetMesh(ug, v, false, z);
  double worstMag = 0, worstZ = 0;
  for (vtkIdType i = 0; i < ug->GetNumberOfPoints(); ++i)
  {
    const double* t = v->GetTuple3(i);
    const double m = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    worstMag =
      std::max(worstMag, std::abs(mm.Points4[4 * i + 3] - psi::UnitScalar(mm.ScalarRange, m)));
    worstZ =
      std::max(worstZ, std::abs(mz.Points4[4 * i + 3] - psi::UnitScalar(mz.ScalarRange, t[2])));
  }
  PSI_CHECK(worstMag < 1e-6 && worstZ < 1e-6, "magnitude (%g) and component 2 (%g) gathered",
    worstMag, worstZ);
}

// The points carry their scalars as fractions of the range, computed in double, whatever the
// range: constant fields (ParaView widens 0 to [0, 1.18e-38]), ranges narrower than the
// smallest normal float, and fields far from 0 beside their width all reach the GPU as [0, 1].
void TestUnitScalars()
{
  auto ug = Tetrahedralized(3);
  const vtkIdType np = ug->GetNumberOfPoints();
  struct Field
  {
    const char* Name;
    double Offset, Width; // s = Offset + Width * f, f in [0, 1] (0 everywhere when Width is 0)
  };
  const Field fields[] = { { "zero", 0, 0 }, { "-2", -2, 0 }, { "1e-30", 1e-30, 0 },
    { "1e30", 1e30, 0 }, { "denormal width", 0, 1e-39 }, { "1e30 + 1e20 f", 1e30, 1e20 },
    { "-1e-300 + 1e-310 f", -1e-300, 1e-310 } };
  for (const Field& field : fields)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetNumberOfTuples(np);
    for (vtkIdType i = 0; i < np; ++i)
    {
      double x[3];
      ug->GetPoint(i, x);
      a->SetValue(i, field.Offset + field.Width * (x[0] + 2 * x[1] + 4 * x[2]) / 7.0);
    }
    psi::TetMesh m = psi::GatherTetMesh(ug, a, false);
    double lo = 2, hi = -1, worst = 0;
    for (vtkIdType i = 0; i < np; ++i)
    {
      const float u = m.Points4[4 * i + 3];
      lo = std::min<double>(lo, u);
      hi = std::max<double>(hi, u);
      worst = std::max(worst, std::abs(u - psi::UnitScalar(m.ScalarRange, a->GetValue(i))));
    }
    const bool constant = field.Width == 0;
    PSI_CHECK(m.ScalarRange[0] == a->GetRange()[0] && m.ScalarRange[1] > m.ScalarRange[0] &&
        lo == 0 && hi == (constant ? 0.0 : 1.0) && worst < 1e-6,
      "%s: range [%g, %g], the points' fractions span [%g, %g] (off by %g)", field.Name,
      m.ScalarRange[0], m.ScalarRange[1], lo, hi, worst);
    // a new time step is normalized over its own range
    for (vtkIdType i = 0; i < np; ++i)
    {
      a->SetValue(i, 3 - a->GetValue(i));
    }
    a->Modified();
    PSI_CHECK(psi::UpdateTetMeshScalars(m, a), "%s: new time step taken", field.Name);
    PSI_CHECK(m.ScalarRange[0] == a->GetRange()[0] &&
        std::abs(m.Points4[3] - psi::UnitScalar(m.ScalarRange, a->GetValue(0))) < 1e-6,
      "%s: the new step's range [%g, %g] and fractions", field.Name, m.ScalarRange[0],
      m.ScalarRange[1]);
  }
}
// A point that no cell uses, near or far (a shared point list): the mesh's shift and bounds, and
// psi::CellPointBounds, are those of the points the cells use, in 64- and 32-bit connectivity and
// through the generic cell access of a vtkDataSet that is no vtkUnstructuredGrid.
void TestUnusedPoints()
{
  for (double far : { 1e4, 1e7 })
  {
    for (bool use32 : { false, true })
    {
      vtkSmartPointer<vtkUnstructuredGrid> ug = Tetrahedralized(4);
      if (use32)
      {
        ug->GetCells()->ConvertTo32BitStorage();
      }
      double clean[6];
      ug->GetBounds(clean);
      const psi::TetMesh reference =
        psi::GatherTetMesh(ug, ug->GetPointData()->GetArray("s"), false);
      ug->GetPoints()->InsertNextPoint(far, far, far);
      vtkDataArray* s = ug->GetPointData()->GetArray("s");
      s->InsertNextTuple1(s->GetTuple1(0));
      ug->GetPoints()->Modified(); // InsertNextPoint leaves the points' time as it was
      double used[6];
      PSI_CHECK(psi::CellPointBounds(ug, used) && std::equal(used, used + 6, clean) &&
          ug->GetBounds()[1] == far,
        "unused point at %g (%s ids): the cells' bounds [%g, %g] are the clean mesh's", far,
        use32 ? "32-bit" : "64-bit", used[0], used[1]);
      const psi::TetMesh m = psi::GatherTetMesh(ug, s, false);
      PSI_CHECK(std::equal(m.Shift, m.Shift + 3, reference.Shift) &&
          std::equal(m.Bounds, m.Bounds + 6, reference.Bounds),
        "unused point at %g: the mesh's shift (%g, %g, %g) and bounds are the clean mesh's", far,
        m.Shift[0], m.Shift[1], m.Shift[2]);
    }
  }
  vtkNew<vtkImageData> image; // no connectivity array: cell by cell
  image->SetDimensions(3, 3, 3);
  double b[6];
  PSI_CHECK(psi::CellPointBounds(image, b) && b[1] == 2 && b[5] == 2,
    "image data: the cells' bounds are its own");
  vtkNew<vtkUnstructuredGrid> none; // points, no cell
  none->SetPoints(vtkSmartPointer<vtkPoints>::New());
  none->GetPoints()->InsertNextPoint(1, 2, 3);
  PSI_CHECK(!psi::CellPointBounds(none, b), "no cell: no bounds");
}
} // namespace

int main()
{
  TestUnusedPoints();
  TestFilterNeighbors();
  TestUnitScalars();
  TestBorrowedCells();
  TestSkippedCells();
  TestCellScalars();
  TestStaleArray();
  TestTimeStep();
  TestVectorComponents();
  return psitest::Report("TestTetMesh");
}
