// The transfer functions of the GL image tests: a color map, an opacity function and the volume
// property holding them, the color maps the tests share, and the exact reference
// (PsiReferenceRaycaster) of a mesh drawn with them.
#ifndef PsiTestTransferFunction_h
#define PsiTestTransferFunction_h

#include "PsiReferenceRaycaster.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

namespace psitest
{
/// A color map and an opacity function, and the volume property that holds them with the
/// opacity's unit distance.
struct TransferFunction
{
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkVolumeProperty> Property;

  explicit TransferFunction(double unitDistance = 1.0)
  {
    this->Property->SetColor(this->Color);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetScalarOpacityUnitDistance(unitDistance);
  }
};

/// Blue (0.1, 0.3, 1.0) at `lo` to yellow (1.0, 0.8, 0.1) at `hi`, linear in RGB: one linear
/// piece, which a cell's linear scalar carries exactly.
inline void BlueToYellow(vtkColorTransferFunction* color, double lo, double hi)
{
  color->SetColorSpaceToRGB();
  color->AddRGBPoint(lo, 0.1, 0.3, 1.0);
  color->AddRGBPoint(hi, 1.0, 0.8, 0.1);
}

/// Blue (0.1, 0.2, 0.9) at `lo`, near white at the middle, red (0.9, 0.15, 0.1) at `hi`, linear
/// in RGB between.
inline void BlueWhiteRed(vtkColorTransferFunction* color, double lo, double hi)
{
  color->SetColorSpaceToRGB();
  color->AddRGBPoint(lo, 0.1, 0.2, 0.9);
  color->AddRGBPoint(0.5 * (lo + hi), 0.95, 0.95, 0.9);
  color->AddRGBPoint(hi, 0.9, 0.15, 0.1);
}

/// Opacity `a0` at `lo` to `a1` at `hi`, linear.
inline void LinearOpacity(vtkPiecewiseFunction* opacity, double lo, double hi, double a0, double a1)
{
  opacity->AddPoint(lo, a0);
  opacity->AddPoint(hi, a1);
}

/// The reference of `grid` (point scalars, tetrahedra) with tau = opacity / unit; the transfer
/// function's control points become the reference's breakpoints.
inline psi::ReferenceScene MakeReferenceScene(vtkUnstructuredGrid* grid,
  vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity, double unit)
{
  psi::ReferenceScene ref;
  vtkDataArray* sc = grid->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[3];
    grid->GetPoint(i, p);
    ref.Points.push_back({ { p[0], p[1], p[2] } });
    ref.Scalars.push_back(sc->GetComponent(i, 0));
  }
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const vtkIdType* pts;
    vtkIdType n;
    grid->GetCellPoints(c, n, pts);
    ref.Tets.push_back({ { int(pts[0]), int(pts[1]), int(pts[2]), int(pts[3]) } });
  }
  ref.Transfer = [color, opacity, unit](double v, double out[4])
  {
    color->GetColor(v, out);
    out[3] = opacity->GetValue(v) / unit;
  };
  for (int i = 0; i < color->GetSize(); ++i)
  {
    double node[6];
    color->GetNodeValue(i, node);
    ref.Breakpoints.push_back(node[0]);
  }
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double node[4];
    opacity->GetNodeValue(i, node);
    ref.Breakpoints.push_back(node[0]);
  }
  return ref;
}

/// The reference of `grid` drawn with `tf` (its property's unit distance).
inline psi::ReferenceScene MakeReferenceScene(vtkUnstructuredGrid* grid, const TransferFunction& tf)
{
  return MakeReferenceScene(
    grid, tf.Color, tf.Opacity, tf.Property->GetScalarOpacityUnitDistance());
}
} // namespace psitest

#endif
