// PsiTransferFunctionNodes: the transfer function as a piecewise-linear list of nodes taken
// from the functions themselves (GL-free), for exact adaptive sampling (Moreland 2004,
// dissertation, §4.3): a ray segment split at the nodes has color and attenuation linear on each
// piece, and each piece is integrated exactly. Unlike the sampled table (PsiTransferFunctionTable),
// nothing narrower than its sample spacing is lost: a node sits on every control point where the
// function bends, a step gives two nodes at one scalar (its left and right values), and where a
// color map bends between its control points (Diverging, Lab, HSV interpolation) nodes are added
// until linear interpolation is within a tolerance of the map.
#ifndef PsiTransferFunctionNodes_h
#define PsiTransferFunctionNodes_h

#include "PsiVolumeCoreModule.h"

#include <vector>

class vtkVolumeProperty;

namespace psi
{
struct TransferFunctionTable;

struct PSIVOLUMECORE_EXPORT TransferFunctionNodes
{
  std::vector<double> Scalars; ///< ascending (equal at a step), first and last at the range ends
  std::vector<float> Rgba;     ///< 4 per node: L.r, L.g, L.b, tau (the table's convention)
  /// The largest distance between the exact function and the nodes' interpolation (color, and
  /// opacity: tau times the unit distance; checked at three points per interval): at most the
  /// tolerance, unless the node budget ran out first.
  double MaxDeviation = 0;

  int Size() const { return static_cast<int>(this->Scalars.size()); }
  /// Linear interpolation between the nodes around s (clamped at the ends); at a step, the
  /// value on its right.
  void Lookup(double s, double out[4]) const;
};

/// Nodes of component 0 of `property` over `range`: the range ends, every control point where
/// the function bends or steps, and refinement where the exact function is farther than
/// `tolerance` (in color and in opacity, tau times the unit distance) from linear interpolation
/// between nodes; at most `maxNodes` (bends kept first, refinement stops at the budget).
PSIVOLUMECORE_EXPORT TransferFunctionNodes SampleTransferFunctionNodes(
  vtkVolumeProperty* property, const double range[2], int maxNodes, double tolerance);

/// The largest difference, in color or in opacity (tau times `unitDistance`), between the
/// linearly interpolated `table` and the `nodes` at the nodes: where a piecewise-linear function
/// and its sampled table differ most. Large when the function has a feature (a spike, a step)
/// narrower than the table's sample spacing.
PSIVOLUMECORE_EXPORT double TableDeviation(
  const TransferFunctionTable& table, const TransferFunctionNodes& nodes, double unitDistance);
} // namespace psi

#endif
