// Helpers shared by the GL image tests: the CPU reference scene of a tetrahedral grid and its
// transfer function, and writing an RGB image (doubles in [0, 1], rows from the bottom) as PNG.
#ifndef PsiTestScene_h
#define PsiTestScene_h

#include "PsiReferenceRaycaster.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkRTAnalyticSource.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <string>
#include <vector>

namespace psitest
{
/// The Wavelet source on [-half, half]^3, cells scaled to `cell` units, split into tetrahedra.
inline void MakeWaveletTets(vtkUnstructuredGrid* grid, int half, double cell)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-half, half, -half, half, -half, half);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(wavelet->GetOutputPort());
  vtkNew<vtkTransform> scale;
  scale->Scale(cell, cell, cell);
  vtkNew<vtkTransformFilter> scaled;
  scaled->SetTransform(scale);
  scaled->SetInputConnection(tets->GetOutputPort());
  scaled->Update();
  grid->ShallowCopy(scaled->GetOutput());
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
  ref.Transfer = [color, opacity, unit](double v, double out[4]) {
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

inline void WritePng(const std::string& file, const std::vector<double>& rgb, int w, int h)
{
  vtkNew<vtkImageData> im;
  im->SetDimensions(w, h, 1);
  im->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(im->GetScalarPointer());
  for (size_t i = 0; i < rgb.size(); ++i)
  {
    p[i] = static_cast<unsigned char>(std::min(255.0, std::max(0.0, rgb[i] * 255.0 + 0.5)));
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(file.c_str());
  writer->SetInputData(im);
  writer->Write();
}
} // namespace psitest

#endif
