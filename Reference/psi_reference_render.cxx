// psi_reference_render: the exact CPU reference image (PsiReferenceRaycaster) of a mesh, a
// transfer function and a camera written by a script, for accuracy reports
// (the package module psivolume.accuracy, Python/psivolume/accuracy.py). Not part of the plugin.
//
// Usage: psi_reference_render MESH.vtu SCENE.txt OUT.raw
//   MESH.vtu   an unstructured grid; non-tetrahedral cells are split by vtkDataSetTriangleFilter
//              (as ParaView's 'Volume' does); cell scalars get private points per tetrahedron
//   SCENE.txt  the scene file: array and association, component, size, background, unit,
//              ndc_to_world and the transfer function's table (PsiReferenceSceneFile.h)
//   OUT.raw    W * H * 3 float64 RGB in [0, 1] (not clamped), rows from the bottom
// Prints the seconds the ray casting took. A failure exits 2, its reason the last line on stderr.
#include "PsiReferenceRaycaster.h"
#include "PsiReferenceSceneFile.h"

#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// The table, linear between its rows and clamped outside, as the transfer function.
void SetTransfer(const psi::ReferenceSceneFile& s, psi::ReferenceScene& ref)
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
  psi::ReferenceSceneFile s;
  std::string why = psi::ReadReferenceSceneFile(argv[2], s);
  if (!why.empty())
  {
    return Fail(why);
  }
  const vtkSmartPointer<vtkUnstructuredGrid> grid = psi::ReadTetrahedralGrid(argv[1]);
  if (!grid)
  {
    return Fail("cannot read the mesh " + std::string(argv[1]) + " (a VTK XML unstructured grid)");
  }
  psi::ReferenceScene ref;
  why = psi::GatherReferenceMesh(grid, s, ref);
  if (!why.empty())
  {
    return Fail(why + " (" + argv[1] + ")");
  }
  SetTransfer(s, ref);
  const psi::ReferenceCamera cam = psi::ReferenceCameraOf(s);
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
