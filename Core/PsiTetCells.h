// PsiTetCells: the four point ids of each tetrahedron, read from the mesh's own 32-bit copy or
// from the input's 64-bit connectivity, which a mesh of tetrahedra only borrows
// (psi::GatherTetMesh): a second copy would cost 16 bytes per cell (138 MB at 8.64M cells).
#ifndef PsiTetCells_h
#define PsiTetCells_h

#include "vtkType.h"

#include <cstddef>
#include <cstdint>

namespace psi
{

struct TetCells
{
  const uint32_t* U32 = nullptr;     ///< 4 ids per tetrahedron, or
  const vtkTypeInt64* I64 = nullptr; ///< 4 ids per tetrahedron (vtkCellArray's 64-bit storage)

  TetCells() = default;
  TetCells(const uint32_t* ids)
    : U32(ids)
  {
  }
  TetCells(const vtkTypeInt64* ids)
    : I64(ids)
  {
  }
  /// Point id `v` (0..3) of tetrahedron `t`.
  uint32_t operator()(size_t t, int v) const
  {
    return this->U32 ? this->U32[4 * t + v] : static_cast<uint32_t>(this->I64[4 * t + v]);
  }
  /// The four point ids of tetrahedron `t`.
  void Get(size_t t, uint32_t ids[4]) const
  {
    for (int v = 0; v < 4; ++v)
    {
      ids[v] = (*this)(t, v);
    }
  }
};

} // namespace psi

#endif
