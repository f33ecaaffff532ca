// PsiAdaptiveNodes: the transfer function's nodes for adaptive sampling
// (psi::TransferFunctionNodes, Moreland 2004, dissertation, §4.3), sent to the fragment shader
// as uniforms (PsiAdaptiveFS.glsl), in the manner of the GPU tables of PsiTransferTextures
// (NeedsUpdate / Update / Activate); and how far the sampled table is from them, which decides
// 'Auto'.
#ifndef PsiAdaptiveNodes_h
#define PsiAdaptiveNodes_h

#include "PsiTransferFunctionNodes.h"

#include "vtkType.h"

class vtkShaderProgram;
class vtkVolumeProperty;
namespace psi
{
struct TransferFunctionTable;
}

class PsiAdaptiveNodes
{
public:
  /// When the property, the range or the sampled table (its version) changed.
  bool NeedsUpdate(vtkVolumeProperty* property, const double range[2], int tableVersion) const;
  /// Samples the nodes of `property` over `range` (at most `maxNodes`, refined to
  /// `tolerance`) and measures `table` (of version `tableVersion`) against them.
  void Update(vtkVolumeProperty* property, const double range[2],
    const psi::TransferFunctionTable& table, int tableVersion, int maxNodes, double tolerance);
  /// Sets tfNodes, tfNodeValues and tfNodeCount.
  void Activate(vtkShaderProgram* program) const;

  int Size() const { return this->Nodes.Size(); }
  /// Whether the nodes follow the transfer function within the tolerance given to Update (a
  /// function with more bends than the node budget is drawn from the table instead).
  bool IsFaithful() const { return this->Faithful; }
  /// psi::TableDeviation of the table given to Update.
  double GetTableDeviation() const { return this->TableDeviation; }

private:
  psi::TransferFunctionNodes Nodes;
  double TableDeviation = 0;
  bool Faithful = true;
  vtkMTimeType Time = 0;
  double Range[2] = { 0, 0 };
  int TableVersion = -1;
};

#endif
