// psi_reference_render: the exact CPU reference image (PsiReferenceRaycaster) of a mesh, a
// transfer function and a camera written by a script, for accuracy reports
// (the package module psivolume.accuracy, Python/psivolume/accuracy.py). Not part of the plugin.
//
// Usage: psi_reference_render MESH.vtu SCENE.txt [MESH.vtu SCENE.txt ...] OUT.raw
//   MESH.vtu   an unstructured grid in world coordinates; non-tetrahedral cells are split by
//              vtkDataSetTriangleFilter (as ParaView's 'Volume' does); cell scalars get private
//              points per tetrahedron
//   SCENE.txt  the scene file: array and association, component, size, background, unit,
//              ndc_to_world and the transfer function's table (PsiReferenceSceneFile.h)
//   OUT.raw    W * H * 3 float64 RGB in [0, 1] (not clamped), rows from the bottom
// Several pairs: several volumes, each with its own transfer function, drawn as media that
// may share space (PsiReferenceMedia.h); the first scene file's size, camera and background.
// Prints the seconds the ray casting took. A failure exits 2, its reason the last line on stderr.
#include "PsiReferenceMedia.h"
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
  ref.Transfer = [table, unit](double v, double out[4])
  {
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

// The volume of `meshPath` and `scenePath` into `ref` (its camera into `cam` when given): an
// empty string, or why not.
std::string ReadVolume(
  const char* meshPath, const char* scenePath, psi::ReferenceScene& ref, psi::ReferenceCamera* cam)
{
  psi::ReferenceSceneFile s;
  std::string why = psi::ReadReferenceSceneFile(scenePath, s);
  if (!why.empty())
  {
    return why;
  }
  const vtkSmartPointer<vtkUnstructuredGrid> grid = psi::ReadTetrahedralGrid(meshPath);
  if (!grid)
  {
    return "cannot read the mesh " + std::string(meshPath) + " (a VTK XML unstructured grid)";
  }
  why = psi::GatherReferenceMesh(grid, s, ref);
  if (!why.empty())
  {
    return why + " (" + meshPath + ")";
  }
  SetTransfer(s, ref);
  if (cam)
  {
    *cam = psi::ReferenceCameraOf(s);
  }
  return std::string();
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 4 || argc % 2 != 0)
  {
    return Fail("usage: psi_reference_render MESH.vtu SCENE.txt [MESH.vtu SCENE.txt ...] OUT.raw");
  }
  const int volumes = (argc - 2) / 2;
  std::vector<psi::ReferenceScene> refs(volumes);
  psi::ReferenceCamera cam;
  for (int k = 0; k < volumes; ++k)
  {
    const std::string why =
      ReadVolume(argv[1 + 2 * k], argv[2 + 2 * k], refs[k], k == 0 ? &cam : nullptr);
    if (!why.empty())
    {
      return Fail(why);
    }
  }
  const char* outPath = argv[argc - 1];
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<const psi::ReferenceScene*> media;
  size_t tets = 0;
  for (const psi::ReferenceScene& r : refs)
  {
    media.push_back(&r);
    tets += r.Tets.size();
  }
  const std::vector<double> image =
    volumes == 1 ? psi::RenderReference(refs[0], cam) : psi::RenderReferenceMedia(media, cam);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream out(outPath, std::ios::binary);
  out.write(reinterpret_cast<const char*>(image.data()),
    static_cast<std::streamsize>(image.size() * sizeof(double)));
  if (!out)
  {
    return Fail("cannot write " + std::string(outPath));
  }
  std::printf("tetrahedra %zu\nseconds %.4f\n", tets, seconds);
  return 0;
}
