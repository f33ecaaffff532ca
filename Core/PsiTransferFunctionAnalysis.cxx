#include "PsiTransferFunctionAnalysis.h"

#include "PsiTransferFunctionTable.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace psi
{
// The transfer function (color and opacity of component 0) at scalar s: rgb, opacity. The color
// map is the continuous one: ParaView's color maps (vtkDiscretizableColorTransferFunction)
// answer GetColor from a 256-entry table by default (Discretize), while its volume mappers sample
// the continuous function (GetTable), as 'Psi Volume' does.
void EvaluateTransferFunction(vtkVolumeProperty* property, double s, double out[4])
{
  out[0] = out[1] = out[2] = 1.0;
  if (property->GetColorChannels(0) == 1)
  {
    if (vtkPiecewiseFunction* gray = property->GetGrayTransferFunction(0))
    {
      out[0] = out[1] = out[2] = gray->GetValue(s);
    }
  }
  else if (vtkColorTransferFunction* rgb = property->GetRGBTransferFunction(0))
  {
    rgb->vtkColorTransferFunction::GetColor(s, out);
  }
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  out[3] = opacity ? opacity->GetValue(s) : 1.0;
}

ScalarComponent ColorMapComponent(vtkVolumeProperty* property, int numberOfComponents)
{
  ScalarComponent c;
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  if (numberOfComponents == 2 && !property->GetIndependentComponents())
  {
    // ParaView's separate opacity array (UseSeparateOpacityArray): color from component 0
    // through the color map, opacity from component 1 through the opacity function, as VTK's
    // vtkProjectedTetrahedraMapper maps two dependent components.
    c.Opacity = 1;
  }
  else if (numberOfComponents > 1 && ctf)
  {
    c.Index = ctf->GetVectorMode() == vtkScalarsToColors::COMPONENT ? ctf->GetVectorComponent()
                                                                    : ScalarComponent::Magnitude;
  }
  return c;
}

std::string UnitDistanceProblem(vtkVolumeProperty* property)
{
  const double unit = property->GetScalarOpacityUnitDistance(0);
  if (unit > 0 && std::isfinite(unit))
  {
    return "";
  }
  return "Psi Volume draws nothing: the opacity unit distance (ScalarOpacityUnitDistance) is " +
    std::to_string(unit) + "; opacity per unit distance needs a positive distance.";
}

std::vector<float> OpacityPrefixCounts(
  const TransferFunctionTable& table, vtkVolumeProperty* property, bool& hasZeroOpacity)
{
  std::vector<char> visible(table.Size);
  for (int i = 0; i < table.Size; ++i)
  {
    visible[i] = table.Rgba[4 * static_cast<size_t>(i) + 3] > 0;
  }
  // A control point with non-zero opacity between two samples that are both zero (a spike
  // narrower than the sample spacing) marks the sample below it: a cell whose range meets the
  // spike meets that sample's interval too.
  vtkPiecewiseFunction* opacity = property ? property->GetScalarOpacity(0) : nullptr;
  const double span = table.OpacityRange[1] - table.OpacityRange[0];
  for (int k = 0; opacity && span > 0 && k < opacity->GetSize(); ++k)
  {
    double n[4];
    opacity->GetNodeValue(k, n);
    const double x = (n[0] - table.OpacityRange[0]) / span * (table.Size - 1);
    if (n[1] > 0 && x >= 0 && x <= table.Size - 1)
    {
      visible[std::min(static_cast<int>(x), table.Size - 1)] = 1;
    }
  }
  std::vector<float> prefix(table.Size);
  float count = 0;
  for (int i = 0; i < table.Size; ++i)
  {
    count += visible[i] ? 1.0f : 0.0f;
    prefix[i] = count;
  }
  hasZeroOpacity = count < table.Size - 1;
  return prefix;
}

double MaxRayOpacity(const TransferFunctionTable& table, double rayLength)
{
  float maxTau = 0;
  for (size_t i = 3; i < table.Rgba.size(); i += 4)
  {
    maxTau = std::max(maxTau, table.Rgba[i]);
  }
  return 1.0 - std::exp(-double(maxTau) * std::max(rayLength, 0.0));
}
} // namespace psi
