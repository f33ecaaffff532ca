#include "PsiCellFaces.h"

#include "vtkCellType.h"
#include "vtkHexagonalPrism.h"
#include "vtkHexahedron.h"
#include "vtkPentagonalPrism.h"
#include "vtkPyramid.h"
#include "vtkWedge.h"

namespace
{
// Adds the faces of a standard linear cell from VTK's static face tables (local ids, -1 ends a
// face shorter than MaximumFaceSize).
template <class CellT>
void AddStandardFaces(const vtkIdType* pts, psi::FaceSet& faces)
{
  faces.Clear();
  for (vtkIdType f = 0; f < CellT::NumberOfFaces; ++f)
  {
    const vtkIdType* local = CellT::GetFaceArray(f);
    for (vtkIdType k = 0; k < CellT::MaximumFaceSize && local[k] >= 0; ++k)
    {
      faces.Ids.push_back(pts[local[k]]);
    }
    faces.Close();
  }
}
} // namespace

namespace psi
{
int LinearCellType(int type)
{
  switch (type)
  {
    case VTK_TETRA:
    case VTK_QUADRATIC_TETRA:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_BEZIER_TETRAHEDRON:
    case VTK_HIGHER_ORDER_TETRAHEDRON:
      return VTK_TETRA;
    case VTK_HEXAHEDRON:
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON:
    case VTK_BEZIER_HEXAHEDRON:
    case VTK_HIGHER_ORDER_HEXAHEDRON:
      return VTK_HEXAHEDRON;
    case VTK_WEDGE:
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_LAGRANGE_WEDGE:
    case VTK_BEZIER_WEDGE:
    case VTK_HIGHER_ORDER_WEDGE:
      return VTK_WEDGE;
    case VTK_PYRAMID:
    case VTK_QUADRATIC_PYRAMID:
    case VTK_TRIQUADRATIC_PYRAMID:
    case VTK_LAGRANGE_PYRAMID:
    case VTK_BEZIER_PYRAMID:
    case VTK_HIGHER_ORDER_PYRAMID:
      return VTK_PYRAMID;
    case VTK_VOXEL:
    case VTK_PENTAGONAL_PRISM:
    case VTK_HEXAGONAL_PRISM:
    case VTK_POLYHEDRON:
      return type;
    default:
      return VTK_EMPTY_CELL;
  }
}

bool StandardCellFaces(int linearType, const vtkIdType* pts, FaceSet& faces)
{
  switch (linearType)
  {
    case VTK_HEXAHEDRON:
      AddStandardFaces<vtkHexahedron>(pts, faces);
      return true;
    case VTK_VOXEL:
    {
      const vtkIdType h[8] = { pts[0], pts[1], pts[3], pts[2], pts[4], pts[5], pts[7], pts[6] };
      AddStandardFaces<vtkHexahedron>(h, faces);
      return true;
    }
    case VTK_WEDGE:
      AddStandardFaces<vtkWedge>(pts, faces);
      return true;
    case VTK_PYRAMID:
      AddStandardFaces<vtkPyramid>(pts, faces);
      return true;
    case VTK_PENTAGONAL_PRISM:
      AddStandardFaces<vtkPentagonalPrism>(pts, faces);
      return true;
    case VTK_HEXAGONAL_PRISM:
      AddStandardFaces<vtkHexagonalPrism>(pts, faces);
      return true;
    default:
      return false;
  }
}

void PolyhedronFaces(vtkIdType nfaces, const vtkIdType* stream, vtkIdType length, FaceSet& faces)
{
  faces.Clear();
  const vtkIdType* end = stream ? stream + length : stream;
  for (vtkIdType f = 0; f < nfaces && stream < end; ++f)
  {
    const vtkIdType n = *stream++;
    if (n < 0 || n > end - stream)
    {
      break; // a truncated stream: keep the whole faces read so far
    }
    faces.Ids.insert(faces.Ids.end(), stream, stream + n);
    stream += n;
    faces.Close();
  }
}

vtkIdType StructuredHexCorners(const int dims[3], vtkIdType cellId, vtkIdType hex[8])
{
  const vtkIdType cx = dims[0] - 1, cy = dims[1] - 1;
  const vtkIdType i = cellId % cx, j = (cellId / cx) % cy, k = cellId / (cx * cy);
  const vtkIdType nx = dims[0], nxy = static_cast<vtkIdType>(dims[0]) * dims[1];
  const vtkIdType base = i + j * nx + k * nxy;
  hex[0] = base;
  hex[1] = base + 1;
  hex[2] = base + 1 + nx;
  hex[3] = base + nx;
  for (int c = 0; c < 4; ++c)
  {
    hex[c + 4] = hex[c] + nxy;
  }
  return i + j + k;
}
} // namespace psi
