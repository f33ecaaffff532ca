// PsiReferenceSceneFile: the exact reference's input as a script writes it (psivolume.accuracy
// Capture: a mesh.vtu and a scene file), read into a psi::ReferenceScene and a
// psi::ReferenceCamera. Read by psi_reference_render and by Benchmarks/bench_saturation.
//
// The scene file: lines of "key values":
//   array NAME (in double quotes, \" and \\ inside, when it holds a blank or a quote; the bytes of
//     the mesh's name) | association points|cells (where NAME is)
//   component K (-1: magnitude) | size W H | background R G B
//   unit U (ScalarOpacityUnitDistance) | ndc_to_world M00 .. M33 (row-major)
//   tf N, then N lines "s r g b opacity" (sorted by s; linear in between, clamped outside; every
//     s is a breakpoint of the reference, tau = opacity / U)
#ifndef PsiReferenceSceneFile_h
#define PsiReferenceSceneFile_h

#include "PsiReferenceRaycaster.h"

#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

class vtkUnstructuredGrid;

namespace psi
{

/// The values of a scene file.
struct ReferenceSceneFile
{
  std::string Array;
  std::string Association; ///< "points" or "cells"
  int Component = -1;
  int Width = 256, Height = 256;
  std::array<double, 3> Background{ { 0, 0, 0 } };
  double Unit = 1;
  std::array<double, 16> NdcToWorld{};
  std::vector<std::array<double, 5>> Table; ///< s, r, g, b, opacity
};

/// Reads the scene file at `path` into `s`: an empty string, or why its values cannot be used.
std::string ReadReferenceSceneFile(const char* path, ReferenceSceneFile& s);

/// The VTK XML unstructured grid at `path` with its cells split into tetrahedra by
/// vtkDataSetTriangleFilter (as ParaView's 'Volume' does); null when the file cannot be read.
vtkSmartPointer<vtkUnstructuredGrid> ReadTetrahedralGrid(const char* path);

/// Adds the grid's tetrahedra to `ref` with the scalars of the scene file's array and association
/// (a point and a cell array may share a name): point scalars shared, cell scalars on private
/// points. An empty string, or why not.
std::string GatherReferenceMesh(
  vtkUnstructuredGrid* grid, const ReferenceSceneFile& s, ReferenceScene& ref);

/// The scene file's camera: its size, ndc_to_world and background.
ReferenceCamera ReferenceCameraOf(const ReferenceSceneFile& s);

} // namespace psi

#endif
