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
// The transfer function (color and opacity of component 0) at scalar s: rgb, opacity.
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
    rgb->GetColor(s, out);
  }
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  out[3] = opacity ? opacity->GetValue(s) : 1.0;
}

// Control points of the color and opacity functions strictly inside the scalar range where the
// transfer function bends (not collinear with its neighbouring nodes): the scalars where a
// segment must be split for color and attenuation to be linear on each piece (Moreland §4.3).
std::vector<float> TransferFunctionKinks(
  vtkVolumeProperty* property, const double range[2], int maxNodes)
{
  std::vector<double> nodes;
  auto add = [&](double x) {
    if (x > range[0] && x < range[1])
    {
      nodes.push_back(x);
    }
  };
  if (property->GetColorChannels(0) == 1)
  {
    if (vtkPiecewiseFunction* gray = property->GetGrayTransferFunction(0))
    {
      for (int i = 0; i < gray->GetSize(); ++i)
      {
        double n[4];
        gray->GetNodeValue(i, n);
        add(n[0]);
      }
    }
  }
  else if (vtkColorTransferFunction* rgb = property->GetRGBTransferFunction(0))
  {
    for (int i = 0; i < rgb->GetSize(); ++i)
    {
      double n[6];
      rgb->GetNodeValue(i, n);
      add(n[0]);
    }
  }
  if (vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0))
  {
    for (int i = 0; i < opacity->GetSize(); ++i)
    {
      double n[4];
      opacity->GetNodeValue(i, n);
      add(n[0]);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::vector<float> kinks;
  const double span = range[1] - range[0];
  for (size_t k = 0; k < nodes.size(); ++k)
  {
    const double a = k > 0 ? nodes[k - 1] : range[0];
    const double b = k + 1 < nodes.size() ? nodes[k + 1] : range[1];
    const double x = nodes[k];
    // sampled just around the node, so that a step (two nodes at one scalar) counts too
    const double h = 1e-6 * span;
    double fa[4], fb[4], fx[4], fl[4], fr[4];
    EvaluateTransferFunction(property, a, fa);
    EvaluateTransferFunction(property, b, fb);
    EvaluateTransferFunction(property, x, fx);
    EvaluateTransferFunction(property, std::max(a, x - h), fl);
    EvaluateTransferFunction(property, std::min(b, x + h), fr);
    const double w = (x - a) / std::max(b - a, 1e-300);
    double bend = 0;
    for (int c = 0; c < 4; ++c)
    {
      bend = std::max(bend, std::abs(fx[c] - (fa[c] + w * (fb[c] - fa[c]))));
      bend = std::max(bend, std::abs(fl[c] - fr[c]) - 1e-3);
    }
    if (bend > 1e-4)
    {
      kinks.push_back(static_cast<float>(x));
    }
  }
  if (kinks.size() > static_cast<size_t>(maxNodes))
  {
    // evenly thinned: a transfer function this detailed is better served by the table anyway
    std::vector<float> thin;
    const size_t n = static_cast<size_t>(maxNodes);
    for (size_t i = 0; i < n; ++i)
    {
      thin.push_back(kinks[i * (kinks.size() - 1) / (n - 1)]);
    }
    kinks.swap(thin);
  }
  return kinks;
}

ScalarComponent ColorMapComponent(vtkVolumeProperty* property, int numberOfComponents)
{
  ScalarComponent c;
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  if (numberOfComponents > 1 && ctf)
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

std::vector<float> OpacityPrefixCounts(const TransferFunctionTable& table, bool& hasZeroOpacity)
{
  std::vector<float> prefix(table.Size);
  float count = 0;
  for (int i = 0; i < table.Size; ++i)
  {
    count += table.Rgba[4 * static_cast<size_t>(i) + 3] > 0 ? 1.0f : 0.0f;
    prefix[i] = count;
  }
  hasZeroOpacity = count < table.Size - 1;
  return prefix;
}

} // namespace psi
