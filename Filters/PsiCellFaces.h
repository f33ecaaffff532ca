// PsiCellFaces: the faces of VTK's linear 3D cells as polygons of global point ids, the input of
// the conforming split (PsiConformingDiagonals.h). GL-free; used by
// vtkPsiConformingTetrahedralize.
#ifndef PsiCellFaces_h
#define PsiCellFaces_h

#include "vtkType.h"

#include <cstddef>
#include <vector>

namespace psi
{
/// A cell given by its faces (polygons of global point ids, cyclic order).
struct FaceSet
{
  std::vector<vtkIdType> Ids;     // all face ids, concatenated
  std::vector<vtkIdType> Offsets; // start of each face in Ids, plus the end
  void Clear()
  {
    this->Ids.clear();
    this->Offsets.assign(1, 0);
  }
  void Close() { this->Offsets.push_back(static_cast<vtkIdType>(this->Ids.size())); }
};

/// The type of the linear cell under `type` (a higher-order cell's corners come first in VTK's
/// ordering, so its first point ids are those of the linear cell): VTK_TETRA, VTK_HEXAHEDRON,
/// VTK_VOXEL, VTK_WEDGE, VTK_PYRAMID, VTK_PENTAGONAL_PRISM, VTK_HEXAGONAL_PRISM, VTK_POLYHEDRON,
/// or VTK_EMPTY_CELL when the type is not handled.
int LinearCellType(int type);

/// The faces of a hexahedron, voxel, wedge, pyramid, pentagonal or hexagonal prism (a type
/// returned by LinearCellType) with point ids `pts`, from VTK's static face tables (a voxel's
/// corners are put in hexahedron order first, VTK's voxel face table not being cyclic).
/// Returns false, with `faces` untouched, for any other type.
bool StandardCellFaces(int linearType, const vtkIdType* pts, FaceSet& faces);

/// The faces of a polyhedron from its face stream: nfaces x (npts, ids...), `length` ids in all;
/// a stream shorter than its counts say yields the whole faces it holds.
void PolyhedronFaces(vtkIdType nfaces, const vtkIdType* stream, vtkIdType length, FaceSet& faces);

/// The point ids of hexahedron `cellId` of a structured grid of `dims` points (VTK corner order,
/// cells numbered with i fastest); returns i + j + k.
vtkIdType StructuredHexCorners(const int dims[3], vtkIdType cellId, vtkIdType hex[8]);
} // namespace psi

#endif
