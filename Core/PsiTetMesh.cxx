#include "PsiTetMesh.h"

#include "PsiCellPointBounds.h"
#include "PsiCellTypes.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkType.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace psi
{
namespace
{
// The four point ids of cell c; false when the cell does not have four points (a grid whose
// types disagree with its cells: seen in VTK 9.6 after InsertNextCell on a grid made with
// SetCells(VTK_TETRA, ...), whose types array is a constant).
bool CellPoints(vtkUnstructuredGridBase* input, vtkIdType c, vtkIdList* ids, vtkIdType pts[4])
{
  if (vtkUnstructuredGrid* ug = vtkUnstructuredGrid::SafeDownCast(input))
  {
    // The form with a list: VTK 9.4+ may store 32-bit or fixed-size cells, whose ids it copies
    // there instead of pointing into its own storage.
    vtkIdType npts = 0;
    const vtkIdType* p = nullptr;
    ug->GetCellPoints(c, npts, p, ids);
    if (npts != 4)
    {
      return false;
    }
    std::copy(p, p + 4, pts);
    return true;
  }
  input->GetCellPoints(c, ids);
  if (ids->GetNumberOfIds() != 4)
  {
    return false;
  }
  for (int v = 0; v < 4; ++v)
  {
    pts[v] = ids->GetId(v);
  }
  return true;
}

// Color and, with a separate opacity array, opacity scalar of tuple i; false if either is not
// finite.
bool TupleScalars(vtkDataArray* scalars, vtkIdType i, ScalarComponent c, double& s, double& o)
{
  s = ScalarValue(scalars, i, c);
  o = c.Opacity >= 0 ? scalars->GetComponent(i, c.Opacity) : 0.0;
  return FiniteScalar(s) && FiniteScalar(o);
}

// The scalars of the mesh's points as the input holds them, in double, while the mesh is
// gathered: TetMesh keeps them only as fractions of their range (NormalizeScalars).
struct RawScalars
{
  std::vector<double> S; ///< color scalar per point
  std::vector<double> O; ///< separate opacity scalar per point (empty without one)
};

void AppendPoint(
  TetMesh& m, RawScalars& raw, const double p[3], double s, double o, ScalarComponent c)
{
  m.Points4.insert(m.Points4.end(),
    { static_cast<float>(p[0] - m.Shift[0]), static_cast<float>(p[1] - m.Shift[1]),
      static_cast<float>(p[2] - m.Shift[2]), 0.0f });
  raw.S.push_back(s);
  if (c.Opacity >= 0)
  {
    raw.O.push_back(o);
  }
}

// Point data: every input point once, with its scalar (0 where it is not finite).
void GatherPoints(vtkUnstructuredGridBase* input, vtkDataArray* scalars, ScalarComponent component,
  TetMesh& m, RawScalars& raw, std::vector<char>& finite)
{
  const vtkIdType np = input->GetNumberOfPoints();
  finite.resize(np);
  m.Points4.reserve(4 * static_cast<size_t>(np));
  raw.S.reserve(static_cast<size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    double s, o;
    finite[i] = TupleScalars(scalars, i, component, s, o);
    double p[3];
    input->GetPoint(i, p);
    AppendPoint(m, raw, p, finite[i] ? s : 0.0, finite[i] ? o : 0.0, component);
  }
}

// Cell data: the tetrahedron's own four points, all carrying the cell's scalars.
void AppendCellScalarTet(vtkUnstructuredGridBase* input, const vtkIdType pts[4], double s, double o,
  ScalarComponent c, TetMesh& m, RawScalars& raw)
{
  const uint32_t base = static_cast<uint32_t>(m.NumberOfPoints());
  for (int v = 0; v < 4; ++v)
  {
    double p[3];
    input->GetPoint(pts[v], p);
    AppendPoint(m, raw, p, s, o, c);
    m.Tets.push_back(base + v);
  }
}

void GatherTets(vtkUnstructuredGridBase* input, vtkDataArray* scalars, bool cellScalars,
  ScalarComponent component, const std::vector<char>& pointFinite, TetMesh& m, RawScalars& raw)
{
  const vtkIdType nc = input->GetNumberOfCells();
  m.Tets.reserve(4 * static_cast<size_t>(nc));
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < nc; ++c)
  {
    vtkIdType pts[4];
    if (input->GetCellType(c) != VTK_TETRA || !CellPoints(input, c, ids, pts))
    {
      ++m.NonTetCells;
      continue;
    }
    double cellScalar = 0.0, cellOpacity = 0.0;
    const bool finite = cellScalars
      ? TupleScalars(scalars, c, component, cellScalar, cellOpacity)
      : pointFinite[pts[0]] && pointFinite[pts[1]] && pointFinite[pts[2]] && pointFinite[pts[3]];
    if (!finite)
    {
      ++m.NonFiniteTets;
      continue;
    }
    if (m.SourceCells.empty() && m.NumberOfTets() != static_cast<size_t>(c))
    {
      // a cell was skipped: from now on tetrahedron i is not input cell i
      for (uint32_t t = 0; t < m.NumberOfTets(); ++t)
      {
        m.SourceCells.push_back(t);
      }
    }
    if (!m.SourceCells.empty())
    {
      m.SourceCells.push_back(static_cast<uint32_t>(c));
    }
    if (cellScalars)
    {
      AppendCellScalarTet(input, pts, cellScalar, cellOpacity, component, m, raw);
      continue;
    }
    for (int v = 0; v < 4; ++v)
    {
      m.Tets.push_back(static_cast<uint32_t>(pts[v]));
    }
  }
}

// Point data on cells that are all tetrahedra with finite scalars: the mesh's cells are the
// input's own connectivity (tetrahedron i is cell i, its points the input's), which the mesh
// then reads in place. False, borrowing nothing, otherwise.
bool BorrowTets(vtkUnstructuredGridBase* input, const std::vector<char>& pointFinite, TetMesh& m)
{
  vtkUnstructuredGrid* ug = vtkUnstructuredGrid::SafeDownCast(input);
  vtkCellArray* cells = ug ? ug->GetCells() : nullptr;
  vtkDataArray* types = ug ? CellTypesOf(ug) : nullptr;
  const vtkIdType nc = input->GetNumberOfCells();
  if (!cells || !types || nc == 0 || types->GetNumberOfValues() != nc ||
    cells->GetNumberOfConnectivityIds() != 4 * nc ||
    input->GetNumberOfPoints() >= (vtkIdType(1) << 31))
  {
    return false;
  }
  double typeRange[2];
  types->GetRange(typeRange, 0); // all tetrahedra: the smallest and largest type are VTK_TETRA
  if (typeRange[0] != VTK_TETRA || typeRange[1] != VTK_TETRA ||
    std::find(pointFinite.begin(), pointFinite.end(), 0) != pointFinite.end())
  {
    return false; // cells to skip: gather a copy
  }
  // TetMesh::Cells reads the ids in place, from a contiguous array of either width (32-bit ids
  // are below 2^31, checked above). VTK 9.2 stores them so (Int32 or Int64 storage); VTK 9.4+
  // may also use its fixed-size storages (same connectivity arrays) or a generic array, which
  // is gathered as a copy instead.
  vtkDataArray* ids = cells->GetConnectivityArray();
  const int type = ids ? ids->GetDataType() : VTK_VOID;
  const bool integral = type == VTK_INT || type == VTK_LONG || type == VTK_LONG_LONG ||
    type == VTK_ID_TYPE || type == VTK_TYPE_INT32 || type == VTK_TYPE_INT64;
  if (!integral || !ids->HasStandardMemoryLayout() || ids->GetNumberOfComponents() != 1 ||
    (ids->GetDataTypeSize() != 4 && ids->GetDataTypeSize() != 8))
  {
    return false;
  }
  m.Borrowed = ids;
  return true;
}

// [lo, hi] made a non-empty range (0..1 when nothing was seen).
void SetRange(double lo, double hi, double range[2])
{
  if (!(lo <= hi))
  {
    lo = 0;
    hi = 1;
  }
  if (hi <= lo)
  {
    hi = lo + std::max(1e-6 * std::abs(lo), 1e-12);
  }
  range[0] = lo;
  range[1] = hi;
}

// Scalar ranges of the drawn tetrahedra (never empty; the separate opacity scalars' too) and,
// when `edges`, the longest and shortest edge (MeasureEdgeLengths).
void MeasureTets(TetMesh& m, const RawScalars& raw, bool edges = true)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  double olo = lo, ohi = hi;
  const bool opacity = !raw.O.empty();
  const TetCells cells = m.Cells();
  for (size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    uint32_t v[4];
    cells.Get(t, v);
    for (int a = 0; a < 4; ++a)
    {
      lo = std::min(lo, raw.S[v[a]]);
      hi = std::max(hi, raw.S[v[a]]);
      if (opacity)
      {
        olo = std::min(olo, raw.O[v[a]]);
        ohi = std::max(ohi, raw.O[v[a]]);
      }
    }
  }
  if (edges)
  {
    MeasureEdgeLengths(m);
  }
  SetRange(lo, hi, m.ScalarRange);
  SetRange(olo, ohi, m.OpacityRange);
}

// A fraction of the range, kept finite in float for points no drawn tetrahedron uses.
float UnitFloat(const double range[2], double s)
{
  return static_cast<float>(std::min(std::max(UnitScalar(range, s), -1e6), 1e6));
}

// The points' scalars as fractions of the measured ranges (TetMesh::Points4).
void NormalizeScalars(TetMesh& m, const RawScalars& raw)
{
  for (size_t i = 0; i < raw.S.size(); ++i)
  {
    m.Points4[4 * i + 3] = UnitFloat(m.ScalarRange, raw.S[i]);
  }
  m.Opacity.resize(raw.O.size());
  for (size_t i = 0; i < raw.O.size(); ++i)
  {
    m.Opacity[i] = UnitFloat(m.OpacityRange, raw.O[i]);
  }
}
} // namespace

void MeasureEdgeLengths(TetMesh& m)
{
  double maxEdge2 = 0, minEdge2 = std::numeric_limits<double>::infinity();
  const TetCells cells = m.Cells();
  for (size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    uint32_t v[4];
    cells.Get(t, v);
    for (int a = 0; a < 4; ++a)
    {
      const float* p = &m.Points4[4 * static_cast<size_t>(v[a])];
      for (int c = a + 1; c < 4; ++c)
      {
        const float* q = &m.Points4[4 * static_cast<size_t>(v[c])];
        const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
          (p[2] - q[2]) * (p[2] - q[2]);
        maxEdge2 = std::max(maxEdge2, d2);
        minEdge2 = d2 > 0 ? std::min(minEdge2, d2) : minEdge2;
      }
    }
  }
  m.MaxEdgeLength = std::sqrt(maxEdge2);
  m.MinEdgeLength = std::isfinite(minEdge2) ? std::sqrt(minEdge2) : 0;
}

double ScalarValue(vtkDataArray* array, int64_t i, ScalarComponent c)
{
  const int n = array->GetNumberOfComponents();
  if (c.Index != ScalarComponent::Magnitude || n == 1)
  {
    return array->GetComponent(i, std::min(std::max(c.Index, 0), n - 1));
  }
  double sum = 0;
  for (int k = 0; k < n; ++k)
  {
    const double v = array->GetComponent(i, k);
    sum += v * v;
  }
  return std::sqrt(sum);
}

TetMesh GatherTetMesh(vtkUnstructuredGridBase* input, vtkDataArray* scalars, bool cellScalars,
  ScalarComponent component)
{
  TetMesh m;
  m.CellScalars = cellScalars;
  double b[6];
  if (!CellPointBounds(input, b)) // the points the cells use: an unused point may lie anywhere
  {
    input->GetBounds(b);
  }
  for (int k = 0; k < 3; ++k)
  {
    m.Shift[k] = 0.5 * (b[2 * k] + b[2 * k + 1]);
    m.Bounds[2 * k] = b[2 * k] - m.Shift[k];
    m.Bounds[2 * k + 1] = b[2 * k + 1] - m.Shift[k];
  }
  std::vector<char> pointFinite;
  RawScalars raw;
  if (!cellScalars)
  {
    GatherPoints(input, scalars, component, m, raw, pointFinite);
  }
  if (cellScalars || !BorrowTets(input, pointFinite, m))
  {
    GatherTets(input, scalars, cellScalars, component, pointFinite, m, raw);
  }
  MeasureTets(m, raw);
  NormalizeScalars(m, raw);
  return m;
}

bool UpdateTetMeshScalars(TetMesh& m, vtkDataArray* scalars, ScalarComponent component)
{
  const size_t np = m.NumberOfPoints();
  if (m.CellScalars || m.NonFiniteTets || !scalars ||
    static_cast<size_t>(scalars->GetNumberOfTuples()) != np)
  {
    return false;
  }
  if ((component.Opacity >= 0) != !m.Opacity.empty())
  {
    return false; // a separate opacity array came or went: gather again
  }
  RawScalars raw;
  raw.S.resize(np);
  raw.O.resize(m.Opacity.size());
  for (size_t i = 0; i < np; ++i)
  {
    double o;
    if (!TupleScalars(scalars, static_cast<vtkIdType>(i), component, raw.S[i], o))
    {
      return false;
    }
    if (!raw.O.empty())
    {
      raw.O[i] = o;
    }
  }
  MeasureTets(m, raw, false);
  NormalizeScalars(m, raw);
  return true;
}

bool FaceNeighborsFromArray(const TetMesh& mesh, vtkDataArray* cellNeighbors, int64_t numInputCells,
  std::vector<int32_t>& neighbors)
{
  neighbors.clear();
  if (!cellNeighbors || cellNeighbors->GetNumberOfComponents() != 4 ||
    cellNeighbors->GetNumberOfTuples() != numInputCells || numInputCells >= (int64_t(1) << 31))
  {
    return false;
  }
  const size_t n = mesh.NumberOfTets();
  // input cell -> tetrahedron, -1 for skipped cells
  std::vector<int32_t> tetOfCell;
  if (!mesh.SourceCells.empty())
  {
    tetOfCell.assign(static_cast<size_t>(numInputCells), -1);
    for (size_t t = 0; t < n; ++t)
    {
      tetOfCell[mesh.SourceCells[t]] = static_cast<int32_t>(t);
    }
  }
  neighbors.resize(4 * n);
  for (size_t t = 0; t < n; ++t)
  {
    const vtkIdType cell = mesh.SourceCells.empty() ? t : mesh.SourceCells[t];
    for (int f = 0; f < 4; ++f)
    {
      const double nb = cellNeighbors->GetComponent(cell, f);
      int32_t id = -1;
      if (nb >= 0 && nb < static_cast<double>(numInputCells))
      {
        id = tetOfCell.empty() ? static_cast<int32_t>(nb) : tetOfCell[static_cast<size_t>(nb)];
      }
      neighbors[4 * t + f] = id;
    }
  }
  return true;
}

std::string DescribeSkippedCells(const TetMesh& m)
{
  std::string out;
  if (m.NonTetCells && m.NumberOfTets() == 0 && !m.NonFiniteTets)
  {
    return "found no volume cells in the input (" + std::to_string(m.NonTetCells) +
      " surface, line or vertex cells): nothing to volume-render. Use a Surface representation.";
  }
  if (m.NonTetCells)
  {
    out += "skipped " + std::to_string(m.NonTetCells) +
      " cells that are not linear tetrahedra (e.g. surface cells mixed into the mesh, or input "
      "given to the mapper without tetrahedralization).";
  }
  if (m.NonFiniteTets)
  {
    out += std::string(out.empty() ? "" : " It also ") + "skipped " +
      std::to_string(m.NonFiniteTets) + " tetrahedra with NaN or infinite scalars.";
  }
  return out;
}

std::vector<float> PointGradients(const TetMesh& m)
{
  const size_t np = m.NumberOfPoints();
  std::vector<double> acc(4 * np, 0.0);
  auto cross = [](const double* a, const double* b, double* o)
  {
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
  };
  const TetCells cells = m.Cells();
  for (size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    uint32_t ids[4];
    cells.Get(t, ids);
    const float* p0 = &m.Points4[4 * static_cast<size_t>(ids[0])];
    double e[3][3], ds[3];
    for (int k = 0; k < 3; ++k)
    {
      const float* pk = &m.Points4[4 * static_cast<size_t>(ids[k + 1])];
      for (int c = 0; c < 3; ++c)
      {
        e[k][c] = static_cast<double>(pk[c]) - p0[c];
      }
      ds[k] = static_cast<double>(pk[3]) - p0[3];
    }
    // grad s = (ds1 (e2 x e3) + ds2 (e3 x e1) + ds3 (e1 x e2)) / det[e1 e2 e3]
    double c23[3], c31[3], c12[3];
    cross(e[1], e[2], c23);
    cross(e[2], e[0], c31);
    cross(e[0], e[1], c12);
    const double det = e[0][0] * c23[0] + e[0][1] * c23[1] + e[0][2] * c23[2];
    if (!(std::abs(det) > 0) || !std::isfinite(det))
    {
      continue;
    }
    const double w = std::abs(det) / 6.0; // the tetrahedron's volume
    for (int v = 0; v < 4; ++v)
    {
      double* a = &acc[4 * static_cast<size_t>(ids[v])];
      for (int k = 0; k < 3; ++k)
      {
        a[k] += w * (ds[0] * c23[k] + ds[1] * c31[k] + ds[2] * c12[k]) / det;
      }
      a[3] += w;
    }
  }
  std::vector<float> out(4 * std::max<size_t>(np, 1), 0.0f);
  for (size_t i = 0; i < np; ++i)
  {
    const double w = acc[4 * i + 3];
    for (int k = 0; k < 3 && w > 0; ++k)
    {
      out[4 * i + k] = static_cast<float>(acc[4 * i + k] / w);
    }
  }
  return out;
}

} // namespace psi
