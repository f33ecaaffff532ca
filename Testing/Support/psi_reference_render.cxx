// psi_reference_render: the exact CPU reference image (PsiReferenceRaycaster) of a mesh, a
// transfer function and a camera written by a script, for accuracy reports
// (the package module psivolume.accuracy, Python/psivolume/accuracy.py). Not part of the plugin.
//
// Usage: psi_reference_render MESH.vtu SCENE.txt OUT.raw
//   MESH.vtu   an unstructured grid; non-tetrahedral cells are split by vtkDataSetTriangleFilter
//              (as ParaView's 'Volume' does); cell scalars get private points per tetrahedron
//   SCENE.txt  lines of "key values":
//                array NAME (in double quotes, \" and \\ inside, when it holds a blank or a quote;
//                  the bytes of the mesh's name) | association points|cells (where NAME is)
//                component K (-1: magnitude) | size W H | background R G B
//                unit U (ScalarOpacityUnitDistance) | ndc_to_world M00 .. M33 (row-major)
//                tf N, then N lines "s r g b opacity" (sorted by s; linear in between, clamped
//                outside; every s is a breakpoint of the reference, tau = opacity / U)
//   OUT.raw    W * H * 3 float64 RGB in [0, 1] (not clamped), rows from the bottom
// Prints the seconds the ray casting took. A failure exits 2, its reason the last line on stderr.
#include "PsiReferenceRaycaster.h"

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
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct SceneFile
{
  std::string Array;
  std::string Association; // "points" or "cells"
  int Component = -1;
  int Width = 256, Height = 256;
  std::array<double, 3> Background{ { 0, 0, 0 } };
  double Unit = 1;
  std::array<double, 16> NdcToWorld{};
  std::vector<std::array<double, 5>> Table; // s, r, g, b, opacity
};

// Reads the value of `key`; false for a key the format does not have.
bool ReadValue(std::istream& in, const std::string& key, SceneFile& s)
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

// The scene file's values; an empty string, or why they cannot be used.
std::string ReadScene(const char* path, SceneFile& s)
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

// Tetrahedra of the grid with their scalars: those of the array of the scene's name and
// association (a point and a cell array may share a name); point scalars shared, cell scalars on
// private points. An empty string, or why not.
std::string GatherMesh(vtkUnstructuredGrid* grid, const SceneFile& s, psi::ReferenceScene& ref)
{
  const bool points = s.Association == "points";
  vtkDataArray* pa = points ? grid->GetPointData()->GetArray(s.Array.c_str()) : nullptr;
  vtkDataArray* ca = points ? nullptr : grid->GetCellData()->GetArray(s.Array.c_str());
  if (!pa && !ca)
  {
    return "the mesh has no " + std::string(points ? "point" : "cell") + " array named \"" +
      s.Array + "\"";
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
  return std::string();
}

// The table, linear between its rows and clamped outside, as the transfer function.
void SetTransfer(const SceneFile& s, psi::ReferenceScene& ref)
{
  const auto table = s.Table;
  const double unit = s.Unit;
  ref.Transfer = [table, unit](double v, double out[4]) {
    auto it = std::lower_bound(table.begin(), table.end(), v,
      [](const std::array<double, 5>& row, double x) { return row[0] < x; });
    std::array<double, 5> row;
    if (it == table.begin() || it == table.end())
    {
      row = it == table.end() ? table.back() : table.front();
    }
    else
    {
      const auto& b = *it;
      const auto& a = *(it - 1);
      const double w = b[0] > a[0] ? (v - a[0]) / (b[0] - a[0]) : 1;
      for (int k = 0; k < 5; ++k)
      {
        row[k] = a[k] + w * (b[k] - a[k]);
      }
    }
    out[0] = row[1];
    out[1] = row[2];
    out[2] = row[3];
    out[3] = row[4] / unit;
  };
  for (const auto& row : table)
  {
    ref.Breakpoints.push_back(row[0]);
  }
}

// One line on stderr, the reason of the failure (psivolume.accuracy shows it), and exit code 2.
int Fail(const std::string& reason)
{
  std::cerr << "psi_reference_render: " << reason << std::endl;
  return 2;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    return Fail("usage: psi_reference_render MESH.vtu SCENE.txt OUT.raw");
  }
  SceneFile s;
  std::string why = ReadScene(argv[2], s);
  if (!why.empty())
  {
    return Fail(why);
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(argv[1]))
  {
    return Fail("cannot read the mesh " + std::string(argv[1]) + " (a VTK XML unstructured grid)");
  }
  reader->SetFileName(argv[1]);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(reader->GetOutputPort());
  tets->TetrahedraOnlyOn();
  tets->Update();
  psi::ReferenceScene ref;
  why = GatherMesh(tets->GetOutput(), s, ref);
  if (!why.empty())
  {
    return Fail(why + " (" + argv[1] + ")");
  }
  SetTransfer(s, ref);
  psi::ReferenceCamera cam;
  cam.Width = s.Width;
  cam.Height = s.Height;
  cam.NdcToWorld = s.NdcToWorld;
  cam.Background = s.Background;
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<double> image = psi::RenderReference(ref, cam);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream out(argv[3], std::ios::binary);
  out.write(reinterpret_cast<const char*>(image.data()),
    static_cast<std::streamsize>(image.size() * sizeof(double)));
  if (!out)
  {
    return Fail("cannot write " + std::string(argv[3]));
  }
  std::printf("tetrahedra %zu\nseconds %.4f\n", ref.Tets.size(), seconds);
  return 0;
}
