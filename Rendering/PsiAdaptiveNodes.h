// PsiAdaptiveNodes: the transfer function's nodes for adaptive sampling
// (psi::TransferFunctionNodes, Moreland 2004, dissertation, §4.3), sent to the fragment shader
// as uniforms (PsiAdaptiveFS.glsl): a PsiGpuTable that holds no texture, beside the lookup
// textures (PsiTableTextures.h); and how far the sampled transfer function is from them, which
// decides 'Auto'.
#ifndef PsiAdaptiveNodes_h
#define PsiAdaptiveNodes_h

#include "PsiGpuTable.h"
#include "PsiTransferFunctionNodes.h"

#include "vtkType.h"

class vtkShaderProgram;
class PsiAdaptiveNodes : public PsiGpuTable
{
public:
  /// When the property, the range or the sampled table (its version) changed.
  bool NeedsUpdate(const PsiTableSources& in) const override;
  /// Samples the nodes of the property over the scalar range (at most in.MaxNodes, refined to
  /// in.NodeTolerance) and measures the sampled table (in.Transfer) against them.
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;
  /// Takes `nodes` made elsewhere, over the scalars [0, 1] (several volumes intermixed:
  /// psi::IntermixNodes), with their table's deviation; faithful within `tolerance`.
  void UseNodes(const psi::TransferFunctionNodes& nodes, double deviation, double tolerance);
  /// Sets tfNodes, tfNodeValues and tfNodeCount.
  void Activate(vtkShaderProgram* program) override;
  void ReleaseGraphicsResources(vtkWindow*) override {}

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
  bool Given = false; ///< the nodes are UseNodes', never sampled from a property
};

#endif
