/**
 * @class vtkPsiConformingTetrahedralize
 * @brief Splits every 3D cell of any vtkDataSet into tetrahedra, conformingly, for 'Psi Volume'.
 *
 * Projected-tetrahedra renderers and MPVONC (Williams 1992; Maximo et al. 2010 §3.1) need a
 * tetrahedral mesh in which neighbouring cells share whole faces: a quad face split by one
 * diagonal on one side and by the other diagonal on the other side leaves a crack and breaks the
 * face adjacency.
 *
 * SplitMode:
 * - CONFORMING (default): every polygonal face is triangulated by the fan from its smallest global
 *   point id (for a quad: the diagonal through its smallest id), and each cell is the cone from
 *   its own smallest point id over the triangles of the faces not containing that point. The
 *   faces through the apex are then triangulated by the same rule, so any two cells sharing a
 *   face split it identically, for any mix of hexahedra, voxels, wedges, pyramids, tetrahedra,
 *   pentagonal/hexagonal prisms and (convex) polyhedra. A hexahedron gives 6 tetrahedra, a wedge
 *   3, a pyramid 2. Exact for convex cells; a non-convex polyhedron may give overlapping
 *   tetrahedra.
 * - FIVE_PER_HEX: the literature's 5-tetrahedra split with the diagonals alternating with the
 *   parity of i + j + k, which conforms on structured input only (vtkImageData,
 *   vtkRectilinearGrid, vtkStructuredGrid). Other input falls back to CONFORMING with a warning.
 *
 * Higher-order cells are linearised (their corner points only). Blanked (hidden) cells are
 * skipped. Every output tetrahedron is positively oriented by CGAL's exact orientation predicate
 * (two vertices swapped otherwise); zero-volume tetrahedra (CGAL::COPLANAR, e.g. from collapsed
 * grid edges) are removed and counted (GetNumberOfRemovedDegenerateTets and the field-data array
 * "RemovedDegenerateTets").
 *
 * Output: the input points and point data unchanged; cell data copied to each child tetrahedron;
 * a 4-component int cell array "FaceNeighbors" (face i opposite vertex i, -1 on the boundary) and
 * a bit-flag cell array "BoundaryFaces" (bit i: face i is on the boundary), computed by
 * psi::ComputeTetNeighbors. Non-manifold faces are counted in the field-data array
 * "NonManifoldFaces".
 */
#ifndef vtkPsiConformingTetrahedralize_h
#define vtkPsiConformingTetrahedralize_h

#include "PsiVolumeFiltersModule.h"
#include "vtkUnstructuredGridAlgorithm.h"

class PSIVOLUMEFILTERS_EXPORT vtkPsiConformingTetrahedralize : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkPsiConformingTetrahedralize* New();
  vtkTypeMacro(vtkPsiConformingTetrahedralize, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SplitModes
  {
    CONFORMING = 0,
    FIVE_PER_HEX = 1
  };

  ///@{
  /// How hexahedra are split (see the class documentation). Default CONFORMING.
  vtkSetClampMacro(SplitMode, int, CONFORMING, FIVE_PER_HEX);
  vtkGetMacro(SplitMode, int);
  ///@}

  /// Tetrahedra produced before the removal of the degenerate ones (last execution).
  vtkGetMacro(NumberOfGeneratedTets, vtkIdType);
  /// Zero-volume tetrahedra removed (last execution).
  vtkGetMacro(NumberOfRemovedDegenerateTets, vtkIdType);
  /// Faces shared by more than two output tetrahedra (last execution).
  vtkGetMacro(NumberOfNonManifoldFaces, vtkIdType);
  /// Input cells that were not split: not 3D, or of an unsupported type (last execution).
  vtkGetMacro(NumberOfSkippedCells, vtkIdType);
  /// FIVE_PER_HEX was requested but the input is not structured (last execution).
  vtkGetMacro(FellBackToConforming, bool);

protected:
  vtkPsiConformingTetrahedralize();
  ~vtkPsiConformingTetrahedralize() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SplitMode = CONFORMING;
  vtkIdType NumberOfGeneratedTets = 0;
  vtkIdType NumberOfRemovedDegenerateTets = 0;
  vtkIdType NumberOfNonManifoldFaces = 0;
  vtkIdType NumberOfSkippedCells = 0;
  bool FellBackToConforming = false;

private:
  vtkPsiConformingTetrahedralize(const vtkPsiConformingTetrahedralize&) = delete;
  void operator=(const vtkPsiConformingTetrahedralize&) = delete;

  // The steps of RequestData. Execution holds what they share (defined in the .cxx). A Check
  // step returns false, with the value RequestData must return in `result`, when it ends the
  // execution.
  struct Execution;
  bool CheckInput(vtkDataSet* input, int& result);
  bool ChooseFivePerHex(const Execution& exec);
  bool SplitCells(Execution& exec); // false when aborted
  void SplitStructuredCell(Execution& exec, vtkIdType cellId);
  void SplitUnstructuredCell(Execution& exec, vtkIdType cellId);
  void SplitCell(Execution& exec, vtkIdType cellId, int type, const vtkIdType* pts, vtkIdType npts);
  bool CheckTetrahedra(const Execution& exec, int& result);
  void SetTetrahedra(const Execution& exec, vtkUnstructuredGrid* output);
  bool CopyAttributes(const Execution& exec, vtkUnstructuredGrid* output); // false when aborted
  void AddFaceNeighbors(const Execution& exec, vtkUnstructuredGrid* output);
  void AddCounts(vtkDataSet* input, vtkUnstructuredGrid* output);
};

#endif
