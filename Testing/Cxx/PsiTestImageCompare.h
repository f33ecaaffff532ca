// Measuring a GL test's image against the exact reference (PsiReferenceRaycaster) at the same
// camera, and writing images (RGB doubles in [0, 1], rows from the bottom) as PNG.
#ifndef PsiTestImageCompare_h
#define PsiTestImageCompare_h

#include "PsiReferenceRaycaster.h"
#include "PsiTestCheck.h"
#include "PsiTestView.h"
#include "vtkPsiVolumeMapper.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkProp.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <cmath>
#include <cstdio>

#include <algorithm>
#include <string>
#include <vector>

namespace psitest
{
/// Writes `rgb` (w x h pixels, rows from the bottom) as an 8-bit PNG.
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

struct Result
{
  double Mean = 0, Max = 0;
  int Covered = 0;
  double Outliers = 0; ///< fraction of channels off by more than 0.05 (13/255)
  double P999 = 0;     ///< 99.9th percentile of the channels' errors (a few stray pixels aside)
};

/// The mean and the largest difference of `image`'s channels from `ref`'s, the reference clamped
/// to [0, 1] as an 8-bit image shows it.
struct Difference
{
  double Mean = 0, Max = 0;
};

inline Difference DifferenceFrom(const std::vector<double>& image, const std::vector<double>& ref)
{
  Difference d;
  for (size_t i = 0; i < image.size() && i < ref.size(); ++i)
  {
    const double e = std::abs(image[i] - std::min(1.0, std::max(0.0, ref[i])));
    d.Mean += e;
    d.Max = std::max(d.Max, e);
  }
  d.Mean /= std::max<size_t>(1, image.size());
  return d;
}

/// The largest difference of two images' channels.
inline double LargestDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double worst = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    worst = std::max(worst, std::abs(a[i] - b[i]));
  }
  return worst;
}

/// When the frame drawn last composited front to back with early ray termination: the image
/// `gpu` against the same frame drawn back to front, which must agree within 1/255 (the
/// terminated rays lose at most 1 - psi::SaturatedOpacity of any channel; rounding to 8 bits
/// may show it as one step). Returns the largest difference, or -1 when the frame was drawn
/// back to front.
inline double CheckFrontToBack(
  const std::string& name, vtkRenderWindow* win, vtkVolume* vol, const std::vector<double>& gpu)
{
  vtkPsiVolumeMapper* mapper = vtkPsiVolumeMapper::SafeDownCast(vol->GetMapper());
  if (!mapper || !mapper->GetLastUsedEarlyRayTermination())
  {
    return -1;
  }
  // where the sort broke cycles there is no visibility order: the two directions break them at
  // other cells (nearest or farthest remaining), and only the reference bounds each image
  const bool exactOrder = mapper->GetLastSortCycles() == 0;
  const int own = mapper->GetEarlyRayTermination();
  mapper->SetEarlyRayTermination(psi::EarlyRayTerminations::Off);
  const std::vector<double> back = GrabRGB(win);
  mapper->SetEarlyRayTermination(own);
  win->Render(); // the window shows the frame as drawn, for the caller's next reads
  const double worst = LargestDifference(gpu, back);
  PSI_CHECK(!exactOrder || worst <= 1.0 / 255 + 1e-9,
    "%s: front to back differs from back to front by %g/255", name.c_str(), 255 * worst);
  return worst;
}

/// Renders the current scene, then the same camera with the CPU reference; compares (mean and
/// max absolute error of 8-bit channels in [0, 1], covered pixels). `opaque` geometry is captured
/// (depth and color) without the volume and the `translucent` props. With `outDir`, writes the
/// GPU image, the reference and 8x their difference as PNG.
inline Result Compare(const std::string& name, vtkRenderWindow* win, vtkRenderer* ren,
  vtkVolume* vol, const psi::ReferenceScene& refScene, vtkActor* opaque, const std::string& outDir,
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
  const double againstBack = CheckFrontToBack(name, win, vol, gpu);
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
  char order[64] = "  back to front";
  if (againstBack >= 0)
  {
    std::snprintf(
      order, sizeof(order), "  front to back: %.0f/255 off back to front", 255 * againstBack);
  }
  std::printf(
    "%-28s mean error %.5f  max %.4f  covered pixels %d  over 0.05: %.4f%%  99.9%%: %.4f%s\n",
    name.c_str(), r.Mean, r.Max, r.Covered, 100 * r.Outliers, r.P999, order);
  std::fflush(stdout);
  return r;
}
} // namespace psitest

#endif
