#include "PsiTransferFunctionTable.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

namespace psi
{

void TransferFunctionTable::Lookup(double s, double out[4]) const
{
  const double span = this->Range[1] - this->Range[0];
  double x = span > 0 ? (s - this->Range[0]) / span * (this->Size - 1) : 0.0;
  x = std::min(std::max(x, 0.0), static_cast<double>(this->Size - 1));
  const int i = std::min(static_cast<int>(x), std::max(this->Size - 2, 0));
  const double w = this->Size > 1 ? x - i : 0.0;
  const int j = std::min(i + 1, this->Size - 1);
  for (int k = 0; k < 4; ++k)
  {
    out[k] = this->Rgba[4 * i + k] * (1 - w) + this->Rgba[4 * j + k] * w;
  }
}

double OpacityUnitDistance(vtkVolumeProperty* property)
{
  return std::max(property->GetScalarOpacityUnitDistance(0), 1e-30);
}

TransferFunctionTable SampleTransferFunction(
  vtkVolumeProperty* property, const double range[2], int size, const double* opacityRange)
{
  TransferFunctionTable t;
  t.Size = std::max(size, 2);
  t.Range[0] = range[0];
  t.Range[1] = range[1] > range[0] ? range[1] : range[0];
  const double* orange = opacityRange ? opacityRange : t.Range;
  t.OpacityRange[0] = orange[0];
  t.OpacityRange[1] = orange[1] > orange[0] ? orange[1] : orange[0];
  t.Rgba.resize(4 * static_cast<size_t>(t.Size));
  const double unit = OpacityUnitDistance(property);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const bool gray = property->GetColorChannels(0) == 1;
  vtkColorTransferFunction* rgb = gray ? nullptr : property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* grayFn = gray ? property->GetGrayTransferFunction(0) : nullptr;
  for (int i = 0; i < t.Size; ++i)
  {
    const double s = t.Range[0] + (t.Range[1] - t.Range[0]) * i / (t.Size - 1);
    double c[3] = { 1, 1, 1 };
    if (rgb)
    {
      rgb->vtkColorTransferFunction::GetColor(s, c);
    }
    else if (grayFn)
    {
      c[0] = c[1] = c[2] = grayFn->GetValue(s);
    }
    const double so =
      t.OpacityRange[0] + (t.OpacityRange[1] - t.OpacityRange[0]) * i / (t.Size - 1);
    const double a = opacity ? opacity->GetValue(so) : 1.0;
    float* o = &t.Rgba[4 * static_cast<size_t>(i)];
    o[0] = static_cast<float>(c[0]);
    o[1] = static_cast<float>(c[1]);
    o[2] = static_cast<float>(c[2]);
    o[3] = static_cast<float>(std::max(a, 0.0) / unit);
  }
  return t;
}

} // namespace psi
