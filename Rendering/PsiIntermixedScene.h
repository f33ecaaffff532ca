// PsiIntermixedScene: what the mapper that draws several volumes intermixed is given instead of
// an input and a property (vtkPsiVolumeMapperIntermixed.cxx): their tetrahedra as one mesh, its
// face neighbours, and their transfer functions as one table (Core/PsiIntermixedMesh.h).
#ifndef PsiIntermixedScene_h
#define PsiIntermixedScene_h

#include "PsiTetMesh.h"
#include "PsiTransferFunctionNodes.h"
#include "PsiTransferFunctionTable.h"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

struct PsiIntermixedScene
{
  psi::TetMesh Mesh;
  /// Names the volumes, their meshes' versions and their matrices: the mesh is made again when
  /// it changes.
  std::string Key;
  std::vector<int32_t> Neighbors; ///< 4 per tetrahedron (MPVONC); empty when not asked for
  /// Names the volumes' properties, their modification times and their meshes' ranges: the
  /// table is sampled again when it changes.
  std::string TablesKey;
  psi::TransferFunctionTable Table;
  std::vector<float> OpacityPrefix;
  bool ZeroOpacity = false;
  /// Their adaptive-sampling nodes as one list (psi::IntermixNodes), each volume's within its
  /// share of the node budget, and how far their tables miss them (the largest): 'Auto' weighs it.
  psi::TransferFunctionNodes Nodes;
  double TableDeviation = 0;
  /// Each isovalue (a slot scalar) with its color, its volume's color map at its own value: the
  /// draw's property knows one volume's map only.
  std::vector<std::pair<double, std::array<double, 3>>> IsoColors;
};

#endif
