// Helpers shared by the GL image tests: the CPU reference scene of a tetrahedral grid and its
// transfer function, writing an RGB image (doubles in [0, 1], rows from the bottom) as PNG, and
// measuring a rendered image against the reference at the same camera.
#ifndef PsiTestScene_h
#define PsiTestScene_h

#include "PsiReferenceRaycaster.h"

#include "vtkActor.h"
#include "vtkCamera.h"
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
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkFloatArray.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkAbstractVolumeMapper.h"

#include <cmath>
#include <cstdio>

#include <algorithm>
#include <string>
#include <vector>

namespace psitest
{
/// Adds the 6 Kuhn tetrahedra around the main diagonal of every cube of a lattice of n^3 points
/// with ids i + n (j + n k) (the split of vtkPsiConformingTetrahedralize): long thin cells whose
/// centroid order is wrong across many shared faces.
inline void AddKuhnTets(vtkUnstructuredGrid* grid, int n)
{
  const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  for (int k = 0; k + 1 < n; ++k)
  {
    for (int j = 0; j + 1 < n; ++j)
    {
      for (int i = 0; i + 1 < n; ++i)
      {
        for (const auto& perm : perms)
        {
          int c[3] = { i, j, k };
          vtkIdType ids[4];
          ids[0] = c[0] + n * (c[1] + n * c[2]);
          for (int step = 0; step < 3; ++step)
          {
            ++c[perm[step]];
            ids[step + 1] = c[0] + n * (c[1] + n * c[2]);
          }
          grid->InsertNextCell(VTK_TETRA, 4, ids);
        }
      }
    }
  }
}

/// `image` (a cube of points, with point scalars) as tetrahedra: Kuhn's split (AddKuhnTets) or
/// vtkDataSetTriangleFilter's alternating one.
inline void TetrahedralizeImage(vtkImageData* image, bool kuhn, vtkUnstructuredGrid* grid)
{
  if (!kuhn)
  {
    vtkNew<vtkDataSetTriangleFilter> tets;
    tets->SetInputData(image);
    tets->Update();
    grid->ShallowCopy(tets->GetOutput());
    return;
  }
  vtkNew<vtkPoints> pts;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    pts->InsertNextPoint(image->GetPoint(i));
  }
  grid->SetPoints(pts);
  grid->GetPointData()->SetScalars(image->GetPointData()->GetScalars());
  AddKuhnTets(grid, image->GetDimensions()[0]);
}

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
/// A slanted unlit opaque quad through the middle of the Wavelet meshes ([-half, half] in x, y),
/// flat green so that its color is exact in the reference.
inline vtkSmartPointer<vtkActor> MakeOpaquePlane(double half)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-half, -half, 0.5);
  plane->SetPoint1(half, -half, -1.5);
  plane->SetPoint2(-half, half, 0.5);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(0.2, 0.7, 0.3);
  return actor;
}

/// A perspective camera inside the Wavelet meshes, looking through them, near plane at 0.05.
inline void SetCameraInside(vtkCamera* cam)
{
  cam->SetParallelProjection(0);
  cam->SetPosition(1.3, 0.7, 2.1);
  cam->SetFocalPoint(4, -2, -6);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(60);
  cam->SetClippingRange(0.05, 100);
}

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

/// The GL tests' view: a w x h window without multisampling, one renderer on the dark background
/// the references share, and (with a mapper) a volume drawn by `mapper` with `property`.
struct VolumeView
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;

  VolumeView(int w, int h, vtkAbstractVolumeMapper* mapper, vtkVolumeProperty* property)
  {
    this->Window->SetSize(w, h);
    this->Window->SetMultiSamples(0);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->AddRenderer(this->Renderer);
    if (mapper)
    {
      this->Volume->SetMapper(mapper);
      this->Volume->SetProperty(property);
      this->Renderer->AddVolume(this->Volume);
    }
  }
};

/// Renders `win` and reads its pixels back as RGB in [0, 1], row by row from the bottom.
inline std::vector<double> GrabRGB(vtkRenderWindow* win)
{
  const int W = win->GetSize()[0], H = win->GetSize()[1];
  win->Render();
  vtkNew<vtkUnsignedCharArray> px;
  win->GetPixelData(0, 0, W - 1, H - 1, 0, px);
  std::vector<double> rgb(3 * W * H);
  for (int i = 0; i < 3 * W * H; ++i)
  {
    rgb[i] = px->GetValue(i) / 255.0;
  }
  return rgb;
}

/// The reference ray caster's camera for `ren`'s active camera at w x h pixels, with its
/// background.
inline psi::ReferenceCamera ReferenceCameraOf(vtkRenderer* ren, int w, int h)
{
  psi::ReferenceCamera cam;
  cam.Width = w;
  cam.Height = h;
  vtkNew<vtkMatrix4x4> m;
  m->DeepCopy(ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1));
  m->Invert();
  std::copy(m->GetData(), m->GetData() + 16, cam.NdcToWorld.begin());
  const double* bg = ren->GetBackground();
  cam.Background = { { bg[0], bg[1], bg[2] } };
  return cam;
}

struct Result
{
  double Mean = 0, Max = 0;
  int Covered = 0;
  double Outliers = 0; ///< fraction of channels off by more than 0.05 (13/255)
  double P999 = 0;     ///< 99.9th percentile of the channels' errors (a few stray pixels aside)
};

/// Renders the current scene, then the same camera with the CPU reference; compares (mean and
/// max absolute error of 8-bit channels in [0, 1], covered pixels). `opaque` geometry is captured
/// (depth and color) without the volume and the `translucent` props. With `outDir`, writes the
/// GPU image, the reference and 8x their difference as PNG.
inline Result Compare(const std::string& name, vtkRenderWindow* win, vtkRenderer* ren, vtkVolume* vol,
  const psi::ReferenceScene& refScene, vtkActor* opaque, const std::string& outDir,
  const std::vector<vtkProp*>& translucent = {})
{
  const int W = win->GetSize()[0], H = win->GetSize()[1];
  psi::ReferenceCamera cam = ReferenceCameraOf(ren, W, H);
  const double* bg = ren->GetBackground();
  // Opaque geometry as drawn by GL (its depth and flat color), without the volume.
  if (opaque)
  {
    vol->VisibilityOff();
    for (vtkProp* p : translucent) // the reference composites those itself
    {
      p->VisibilityOff();
    }
    win->Render();
    std::vector<float> z(W * H);
    win->GetZbufferData(0, 0, W - 1, H - 1, z.data());
    cam.OpaqueDepth = z;
    vtkNew<vtkFloatArray> rgba;
    win->GetRGBAPixelData(0, 0, W - 1, H - 1, 0, rgba);
    cam.OpaqueColor.resize(3 * W * H);
    for (int i = 0; i < W * H; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        cam.OpaqueColor[3 * i + k] = rgba->GetValue(4 * i + k);
      }
    }
    vol->VisibilityOn();
    for (vtkProp* p : translucent)
    {
      p->VisibilityOn();
    }
  }
  const std::vector<double> gpu = GrabRGB(win);
  const std::vector<double> ref = psi::RenderReference(refScene, cam);

  Result r;
  std::vector<double> diff(ref.size());
  for (size_t i = 0; i < ref.size(); ++i)
  {
    const double e = std::abs(gpu[i] - std::min(1.0, std::max(0.0, ref[i])));
    r.Mean += e;
    r.Max = std::max(r.Max, e);
    r.Outliers += e > 0.05;
    diff[i] = 8 * e;
  }
  r.Mean /= ref.size();
  r.Outliers /= ref.size();
  {
    std::vector<double> sorted(diff);
    const size_t k = static_cast<size_t>(0.999 * (sorted.size() - 1));
    std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
    r.P999 = sorted[k] / 8; // diff holds 8x the error
  }
  for (int i = 0; i < W * H; ++i)
  {
    double d = 0;
    for (int k = 0; k < 3; ++k)
    {
      d += std::abs(gpu[3 * i + k] - bg[k]);
    }
    r.Covered += d > 2.0 / 255;
  }
  if (!outDir.empty())
  {
    psitest::WritePng(outDir + "/" + name + "_gpu.png", gpu, W, H);
    psitest::WritePng(outDir + "/" + name + "_ref.png", ref, W, H);
    psitest::WritePng(outDir + "/" + name + "_diff8x.png", diff, W, H);
  }
  std::printf("%-28s mean error %.5f  max %.4f  covered pixels %d  over 0.05: %.4f%%  99.9%%: %.4f\n",
    name.c_str(), r.Mean, r.Max, r.Covered, 100 * r.Outliers, r.P999);
  std::fflush(stdout);
  return r;
}
} // namespace psitest

#endif
