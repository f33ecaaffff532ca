#include "PsiAdaptiveNodes.h"

#include "PsiTableTextures.h"
#include "PsiTetMesh.h"
#include "PsiTransferFunctionTable.h"

#include "vtkObject.h"
#include "vtkShaderProgram.h"
#include "vtkVolumeProperty.h"

#include <vector>

bool PsiAdaptiveNodes::NeedsUpdate(const PsiTableSources& in) const
{
  if (this->Given)
  {
    return false; // UseNodes' (several volumes intermixed), not the property's
  }
  return in.Property->GetMTime() != this->Time || this->Range[0] != in.ScalarRange[0] ||
    this->Range[1] != in.ScalarRange[1] || in.Transfer->GetVersion() != this->TableVersion;
}

void PsiAdaptiveNodes::Update(vtkOpenGLRenderWindow*, const PsiTableSources& in)
{
  vtkVolumeProperty* property = in.Property;
  const double* range = in.ScalarRange;
  const int maxNodes = in.MaxNodes;
  const double tolerance = in.NodeTolerance;
  this->TableVersion = in.Transfer->GetVersion();
  this->Nodes = psi::SampleTransferFunctionNodes(property, range, maxNodes, tolerance);
  this->TableDeviation =
    psi::TableDeviation(in.Transfer->GetTable(), this->Nodes, psi::OpacityUnitDistance(property));
  this->Faithful = this->Nodes.MaxDeviation <= tolerance;
  if (!this->Faithful)
  {
    vtkGenericWarningMacro("Psi Volume: the transfer function needs more than "
      << maxNodes << " nodes to be followed within " << tolerance << " (off by "
      << this->Nodes.MaxDeviation << "); adaptive sampling is not used, the sampled table is.");
  }
  this->Time = property->GetMTime();
  this->Range[0] = range[0];
  this->Range[1] = range[1];
}

void PsiAdaptiveNodes::UseNodes(
  const psi::TransferFunctionNodes& nodes, double deviation, double tolerance)
{
  this->Nodes = nodes;
  this->TableDeviation = deviation;
  this->Faithful = nodes.MaxDeviation <= tolerance;
  this->Range[0] = 0; // slot scalars: their own fractions
  this->Range[1] = 1;
  this->Given = true;
}

void PsiAdaptiveNodes::Activate(vtkShaderProgram* program)
{
  const int n = this->Nodes.Size();
  program->SetUniformi("tfNodeCount", n);
  if (n > 0)
  {
    // as fractions of the range, like the points' scalars (psi::TetMesh::Points4)
    std::vector<float> unit(n);
    for (int i = 0; i < n; ++i)
    {
      unit[i] = static_cast<float>(psi::UnitScalar(this->Range, this->Nodes.Scalars[i]));
    }
    program->SetUniform1fv("tfNodes", n, unit.data());
    program->SetUniform4fv(
      "tfNodeValues", n, reinterpret_cast<const float(*)[4]>(this->Nodes.Rgba.data()));
  }
}
