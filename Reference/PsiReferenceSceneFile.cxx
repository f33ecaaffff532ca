#include "PsiReferenceSceneFile.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <istream>

namespace psi
{
namespace
{
// Reads the value of `key`; false for a key the format does not have.
bool ReadValue(std::istream& in, const std::string& key, ReferenceSceneFile& s)
{
  if (key == "array")
  {
    in >> std::quoted(s.Array); // a name may hold blanks (std::quoted reads a bare word too)
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
    in >> s.Background[0] >> s.Background[1] >> s.Background[2];
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
    return false;
  }
  return true;
}

// Component `component` of tuple `i` of `a`, or the tuple's magnitude for component -1 (a
// single-component array gives its value).
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

// Appends point `id` of the grid to `ref` with scalar `s`; its index in `ref`.
int AddPoint(vtkUnstructuredGrid* grid, vtkIdType id, double s, ReferenceScene& ref)
{
  double p[3];
  grid->GetPoint(id, p);
  ref.Points.push_back({ { p[0], p[1], p[2] } });
  ref.Scalars.push_back(s);
  return static_cast<int>(ref.Points.size() - 1);
}
} // namespace

std::string ReadReferenceSceneFile(const char* path, ReferenceSceneFile& s)
{
  std::ifstream in(path);
  if (!in)
  {
    return "cannot open the scene file " + std::string(path);
  }
  std::string key;
  while (in >> key)
  {
    if (!ReadValue(in, key, s))
    {
      return "unknown key '" + key + "' in the scene file " + path;
    }
    if (in.fail())
    {
      return "bad value of '" + key + "' in the scene file " + path;
    }
  }
  if (s.Array.empty() || (s.Association != "points" && s.Association != "cells"))
  {
    return "the scene file " + std::string(path) + " names no array and its association " +
      "(points or cells)";
  }
  if (s.Table.empty() || s.Width <= 0 || s.Height <= 0 || s.Unit <= 0)
  {
    return "the scene file " + std::string(path) + " has no transfer function, size or unit";
  }
  return std::string();
}

vtkSmartPointer<vtkUnstructuredGrid> ReadTetrahedralGrid(const char* path)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(path))
  {
    return nullptr;
  }
  reader->SetFileName(path);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(reader->GetOutputPort());
  tets->TetrahedraOnlyOn();
  tets->Update();
  return tets->GetOutput();
}

std::string GatherReferenceMesh(
  vtkUnstructuredGrid* grid, const ReferenceSceneFile& s, ReferenceScene& ref)
{
  const bool points = s.Association == "points";
  vtkDataArray* pa = points ? grid->GetPointData()->GetArray(s.Array.c_str()) : nullptr;
  vtkDataArray* ca = points ? nullptr : grid->GetCellData()->GetArray(s.Array.c_str());
  if (!pa && !ca)
  {
    return "the mesh has no " + std::string(points ? "point" : "cell") + " array named \"" +
      s.Array + "\"";
  }
  for (vtkIdType i = 0; pa && i < grid->GetNumberOfPoints(); ++i)
  {
    AddPoint(grid, i, ScalarOf(pa, i, s.Component), ref);
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
      tet[v] =
        ca ? AddPoint(grid, pts[v], ScalarOf(ca, c, s.Component), ref) : static_cast<int>(pts[v]);
    }
    ref.Tets.push_back(tet);
  }
  return std::string();
}

ReferenceCamera ReferenceCameraOf(const ReferenceSceneFile& s)
{
  ReferenceCamera cam;
  cam.Width = s.Width;
  cam.Height = s.Height;
  cam.NdcToWorld = s.NdcToWorld;
  cam.Background = s.Background;
  return cam;
}

} // namespace psi
