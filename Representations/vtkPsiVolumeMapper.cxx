#include "vtkPsiVolumeMapper.h"

#include "PsiCompositeFS.h"
#include "PsiIntegrateAverage.h"
#include "PsiIntegrateAverageOpacity.h"
#include "PsiIntegrateFullPreIntegration.h"
#include "PsiIntegrateLinearExact.h"
#include "PsiIntegrateLinearLuminanceAverageOpacity.h"
#include "PsiIntegrateLinearOpacityImproved.h"
#include "PsiIntegratePartialPreIntegration.h"
#include "PsiIntegrationMethods.h"
#include "PsiMPVONCSort.h"
#include "PsiPreIntegrationTable.h"
#include "PsiTetConnectivity.h"
#include "PsiProjectionClasses.h"
#include "PsiShaderComposer.h"
#include "PsiTable.h"
#include "PsiTransferFunctionTable.h"
#include "PsiVisibilitySort.h"
#include "PsiVolumeFS.h"
#include "PsiVolumeGS.h"
#include "PsiVolumeVS.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPiecewiseFunction.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkPropCollection.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Replaces the first occurrence of `tag` in `src`.
void Substitute(std::string& src, const std::string& tag, const std::string& with)
{
  const auto pos = src.find(tag);
  if (pos != std::string::npos)
  {
    src.replace(pos, tag.size(), with);
  }
}

const char* IntegratorSource(int method)
{
  switch (method)
  {
    case vtkPsiVolumeMapper::AVERAGE:
      return PsiIntegrateAverage;
    case vtkPsiVolumeMapper::LINEAR_EXACT:
      return PsiIntegrateLinearExact;
    case vtkPsiVolumeMapper::AVERAGE_OPACITY:
      return PsiIntegrateAverageOpacity;
    case vtkPsiVolumeMapper::LINEAR_LUMINANCE_AVERAGE_OPACITY:
      return PsiIntegrateLinearLuminanceAverageOpacity;
    case vtkPsiVolumeMapper::LINEAR_OPACITY_IMPROVED:
      return PsiIntegrateLinearOpacityImproved;
    case vtkPsiVolumeMapper::FULL_PRE_INTEGRATION:
      return PsiIntegrateFullPreIntegration;
    default:
      return PsiIntegratePartialPreIntegration;
  }
}

// The mesh as uploaded: points (shifted model xyz + scalar) and 4 point ids per tetrahedron.
struct MeshData
{
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 }; // of the shifted points
  std::vector<float> Points4;
  std::vector<uint32_t> Tets;
  double Shift[3] = { 0, 0, 0 };
  double ScalarRange[2] = { 0, 1 };
  vtkIdType NonTetCells = 0;
  vtkIdType NonFiniteTets = 0;
  double MaxEdgeLength = 0; // bounds every segment's length
};

// Gathers tetrahedra and scalars; non-tetrahedral cells and tetrahedra with NaN/Inf scalars are
// skipped and counted. Cell scalars give each tetrahedron four private points.
MeshData GatherMesh(vtkUnstructuredGridBase* input, vtkDataArray* scalars, bool cellScalars)
{
  MeshData m;
  double b[6];
  input->GetBounds(b);
  for (int k = 0; k < 3; ++k)
  {
    m.Shift[k] = 0.5 * (b[2 * k] + b[2 * k + 1]);
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const vtkIdType np = input->GetNumberOfPoints(), nc = input->GetNumberOfCells();
  std::vector<float> pointScalar;
  std::vector<char> pointFinite;
  if (!cellScalars)
  {
    pointScalar.resize(np);
    pointFinite.resize(np);
    for (vtkIdType i = 0; i < np; ++i)
    {
      const double s = scalars->GetComponent(i, 0);
      pointFinite[i] = std::isfinite(s) && std::abs(s) < 1e37;
      pointScalar[i] = pointFinite[i] ? static_cast<float>(s) : 0.0f;
    }
    m.Points4.resize(4 * static_cast<size_t>(np));
    for (vtkIdType i = 0; i < np; ++i)
    {
      double p[3];
      input->GetPoint(i, p);
      float* o = &m.Points4[4 * i];
      o[0] = static_cast<float>(p[0] - m.Shift[0]);
      o[1] = static_cast<float>(p[1] - m.Shift[1]);
      o[2] = static_cast<float>(p[2] - m.Shift[2]);
      o[3] = pointScalar[i];
    }
  }
  m.Tets.reserve(4 * static_cast<size_t>(nc));
  vtkNew<vtkIdList> ids;
  vtkUnstructuredGrid* ug = vtkUnstructuredGrid::SafeDownCast(input);
  for (vtkIdType c = 0; c < nc; ++c)
  {
    if (input->GetCellType(c) != VTK_TETRA)
    {
      ++m.NonTetCells;
      continue;
    }
    vtkIdType pts[4];
    if (ug)
    {
      vtkIdType npts;
      const vtkIdType* p;
      ug->GetCellPoints(c, npts, p);
      std::copy(p, p + 4, pts);
    }
    else
    {
      input->GetCellPoints(c, ids);
      for (int v = 0; v < 4; ++v)
      {
        pts[v] = ids->GetId(v);
      }
    }
    if (cellScalars)
    {
      const double s = scalars->GetComponent(c, 0);
      if (!std::isfinite(s) || std::abs(s) >= 1e37)
      {
        ++m.NonFiniteTets;
        continue;
      }
      lo = std::min(lo, s);
      hi = std::max(hi, s);
      const uint32_t base = static_cast<uint32_t>(m.Points4.size() / 4);
      for (int v = 0; v < 4; ++v)
      {
        double p[3];
        input->GetPoint(pts[v], p);
        m.Points4.insert(m.Points4.end(),
          { static_cast<float>(p[0] - m.Shift[0]), static_cast<float>(p[1] - m.Shift[1]),
            static_cast<float>(p[2] - m.Shift[2]), static_cast<float>(s) });
        m.Tets.push_back(base + v);
      }
      continue;
    }
    bool finite = true;
    for (int v = 0; v < 4; ++v)
    {
      finite = finite && pointFinite[pts[v]];
    }
    if (!finite)
    {
      ++m.NonFiniteTets;
      continue;
    }
    for (int v = 0; v < 4; ++v)
    {
      m.Tets.push_back(static_cast<uint32_t>(pts[v]));
      lo = std::min<double>(lo, pointScalar[pts[v]]);
      hi = std::max<double>(hi, pointScalar[pts[v]]);
    }
  }
  double maxEdge2 = 0;
  for (size_t t = 0; t < m.Tets.size(); t += 4)
  {
    for (int a = 0; a < 4; ++a)
    {
      for (int c = a + 1; c < 4; ++c)
      {
        const float* p = &m.Points4[4 * static_cast<size_t>(m.Tets[t + a])];
        const float* q = &m.Points4[4 * static_cast<size_t>(m.Tets[t + c])];
        const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
          (p[2] - q[2]) * (p[2] - q[2]);
        maxEdge2 = std::max(maxEdge2, d2);
      }
    }
  }
  m.MaxEdgeLength = std::sqrt(maxEdge2);
  for (int k = 0; k < 3; ++k)
  {
    m.Bounds[2 * k] = b[2 * k] - m.Shift[k];
    m.Bounds[2 * k + 1] = b[2 * k + 1] - m.Shift[k];
  }
  if (!(lo <= hi))
  {
    lo = 0;
    hi = 1;
  }
  if (hi <= lo)
  {
    hi = lo + std::max(1e-6 * std::abs(lo), 1e-12);
  }
  m.ScalarRange[0] = lo;
  m.ScalarRange[1] = hi;
  return m;
}

// Whether any visible opaque prop other than `vol` overlaps the volume's bounds: only then can
// opaque geometry cut through cells, which needs the scene depth in the fragment shader.
bool OpaqueGeometryInside(vtkRenderer* ren, vtkVolume* vol)
{
  double vb[6];
  vol->GetBounds(vb);
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* p = props->GetNextProp(it))
  {
    if (p == vol || !p->GetVisibility() || p->IsA("vtkVolume") || !p->HasOpaqueGeometry())
    {
      continue;
    }
    const double* b = p->GetBounds();
    if (b && b[0] <= vb[1] && vb[0] <= b[1] && b[2] <= vb[3] && vb[2] <= b[3] && b[4] <= vb[5] &&
      vb[4] <= b[5])
    {
      return true;
    }
  }
  return false;
}

// Smoothed point gradients of the linear scalar (isosurface normals): every tetrahedron's gradient,
// weighted by its volume, averaged over the tetrahedra sharing the point. xyz + 0 per point.
std::vector<float> PointGradients(const MeshData& m)
{
  const size_t np = m.Points4.size() / 4;
  std::vector<double> acc(4 * np, 0.0);
  for (size_t t = 0; t + 3 < m.Tets.size(); t += 4)
  {
    double V[4][3], s[4];
    for (int v = 0; v < 4; ++v)
    {
      const float* p = &m.Points4[4 * static_cast<size_t>(m.Tets[t + v])];
      V[v][0] = p[0];
      V[v][1] = p[1];
      V[v][2] = p[2];
      s[v] = p[3];
    }
    double e[3][3];
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        e[k][c] = V[k + 1][c] - V[0][c];
      }
    }
    auto cross = [](const double* a, const double* b, double* o) {
      o[0] = a[1] * b[2] - a[2] * b[1];
      o[1] = a[2] * b[0] - a[0] * b[2];
      o[2] = a[0] * b[1] - a[1] * b[0];
    };
    double c23[3], c31[3], c12[3];
    cross(e[1], e[2], c23);
    cross(e[2], e[0], c31);
    cross(e[0], e[1], c12);
    const double det = e[0][0] * c23[0] + e[0][1] * c23[1] + e[0][2] * c23[2];
    if (!(std::abs(det) > 0) || !std::isfinite(det))
    {
      continue;
    }
    const double w = std::abs(det) / 6.0;
    double g[3];
    for (int k = 0; k < 3; ++k)
    {
      g[k] = ((s[1] - s[0]) * c23[k] + (s[2] - s[0]) * c31[k] + (s[3] - s[0]) * c12[k]) / det;
    }
    for (int v = 0; v < 4; ++v)
    {
      double* a = &acc[4 * static_cast<size_t>(m.Tets[t + v])];
      a[0] += w * g[0];
      a[1] += w * g[1];
      a[2] += w * g[2];
      a[3] += w;
    }
  }
  std::vector<float> out(4 * std::max<size_t>(np, 1), 0.0f);
  for (size_t i = 0; i < np; ++i)
  {
    const double w = acc[4 * i + 3];
    for (int k = 0; k < 3 && w > 0; ++k)
    {
      out[4 * i + k] = static_cast<float>(acc[4 * i + k] / w);
    }
  }
  return out;
}

// The transfer function (color and opacity of component 0) at scalar s: rgb, opacity.
void EvaluateTransfer(vtkVolumeProperty* property, double s, double out[4])
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
std::vector<float> TransferFunctionKinks(vtkVolumeProperty* property, const double range[2])
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
    EvaluateTransfer(property, a, fa);
    EvaluateTransfer(property, b, fb);
    EvaluateTransfer(property, x, fx);
    EvaluateTransfer(property, std::max(a, x - h), fl);
    EvaluateTransfer(property, std::min(b, x + h), fr);
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
  if (kinks.size() > static_cast<size_t>(vtkPsiVolumeMapper::MaxAdaptiveNodes))
  {
    // evenly thinned: a transfer function this detailed is better served by the table anyway
    std::vector<float> thin;
    const size_t n = vtkPsiVolumeMapper::MaxAdaptiveNodes;
    for (size_t i = 0; i < n; ++i)
    {
      thin.push_back(kinks[i * (kinks.size() - 1) / (n - 1)]);
    }
    kinks.swap(thin);
  }
  return kinks;
}

// Row-major 4x4 product a * b.
void Multiply(const double a[16], const double b[16], double out[16])
{
  vtkMatrix4x4::Multiply4x4(a, b, out);
}
} // namespace

struct vtkPsiVolumeMapper::Internals
{
  // Mesh
  MeshData Mesh;
  std::vector<float> Centroids;
  std::vector<int32_t> Neighbors; // face neighbours for MPVONC, computed on first use
  std::vector<uint32_t> Order;
  int SortedMethod = -1;
  vtkMTimeType MeshTime = 0;
  // Identity of the uploaded input: switching to an older dataset has a smaller MTime.
  const void* MeshInput = nullptr;
  std::string MeshArrayKey;
  vtkNew<vtkOpenGLBufferObject> PointsBuffer;
  vtkNew<vtkTextureObject> PointsTexture;
  vtkNew<vtkOpenGLBufferObject> GradientBuffer; // smoothed point gradients (isosurfaces only)
  vtkNew<vtkTextureObject> GradientTexture;
  bool GradientsOnGPU = false;
  GLuint TetBuffer = 0;
  GLuint IndexBuffer = 0;
  GLuint VAO = 0;
  bool MeshOnGPU = false;

  // Visibility order
  std::array<double, 16> SortedMCVC{};
  bool SortedParallel = false;
  bool OrderOnGPU = false;

  // Transfer function and Psi table
  vtkNew<vtkTextureObject> TransferTexture;
  vtkMTimeType TransferTime = 0;         // property MTime when last sampled
  psi::TransferFunctionTable Transfer;    // what the texture holds (reused by pre-integration)
  // HAPT §3.5 early discard: prefix counts of samples with non-zero opacity (R32F, N x 1), and
  // whether the opacity function has a zero region at all (else the variant is not compiled).
  vtkNew<vtkTextureObject> OpacityPrefixTexture;
  bool TransferHasZeroOpacity = false;
  int TransferVersion = 0;                // bumped only when the sampled content changes
  int PreVersion = -1;
  double TransferRange[2] = { 0, 0 };
  int TransferSamples = 0;
  vtkNew<vtkTextureObject> PsiTexture;
  int PsiSize = 0;
  vtkNew<vtkTextureObject> PreTexture;
  psi::PreIntegrationTable PreTable; // the table on the GPU (its Rgba cleared after upload)
  bool PreValid = false;

  // Frame buffers: the scene's depth as the float target's depth attachment (hardware depth test),
  // and a second copy to sample when a shader variant reads it.
  vtkNew<vtkTextureObject> DepthTexture;
  vtkNew<vtkTextureObject> DepthSampleTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  int Size[2] = { 0, 0 };
  std::unique_ptr<vtkOpenGLQuadHelper> Composite;

  vtkShaderProgram* Program = nullptr;
  std::string ProgramKey;
  std::array<int, 81> ClassTable{};
  vtkWindow* Context = nullptr;

  void Release(vtkWindow* win)
  {
    if (this->Context && this->MeshOnGPU)
    {
      glDeleteBuffers(1, &this->TetBuffer);
      glDeleteBuffers(1, &this->IndexBuffer);
      glDeleteVertexArrays(1, &this->VAO);
    }
    this->TetBuffer = this->IndexBuffer = this->VAO = 0;
    this->PointsBuffer->ReleaseGraphicsResources();
    this->PointsTexture->ReleaseGraphicsResources(win);
    this->GradientBuffer->ReleaseGraphicsResources();
    this->GradientTexture->ReleaseGraphicsResources(win);
    this->GradientsOnGPU = false;
    this->TransferTexture->ReleaseGraphicsResources(win);
    this->OpacityPrefixTexture->ReleaseGraphicsResources(win);
    this->Transfer = psi::TransferFunctionTable();
    this->PsiTexture->ReleaseGraphicsResources(win);
    this->PreTexture->ReleaseGraphicsResources(win);
    this->PreValid = false;
    this->DepthTexture->ReleaseGraphicsResources(win);
    this->DepthSampleTexture->ReleaseGraphicsResources(win);
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(win);
      this->Framebuffer = nullptr;
    }
    this->Composite.reset();
    this->Program = nullptr;
    this->ProgramKey.clear();
    this->MeshOnGPU = this->OrderOnGPU = false;
    this->MeshTime = this->TransferTime = 0;
    this->PsiSize = 0;
    this->Size[0] = this->Size[1] = 0;
    this->Context = nullptr;
  }
};

vtkStandardNewMacro(vtkPsiVolumeMapper);

vtkPsiVolumeMapper::vtkPsiVolumeMapper()
  : Impl(new Internals)
{
  const auto& table = psi::GetProjectionClassTable();
  for (int i = 0; i < 81; ++i)
  {
    this->Impl->ClassTable[i] = psi::PackProjectionClass(table[i]);
  }
}

vtkPsiVolumeMapper::~vtkPsiVolumeMapper() = default;

void vtkPsiVolumeMapper::SetNumberOfIsosurfaces(int n)
{
  n = std::max(n, 0);
  if (static_cast<size_t>(n) != this->IsosurfaceValues.size())
  {
    this->IsosurfaceValues.resize(n, 0.0);
    this->Modified();
  }
}

void vtkPsiVolumeMapper::SetIsosurfaceValue(int i, double value)
{
  if (i < 0)
  {
    return;
  }
  if (static_cast<size_t>(i) >= this->IsosurfaceValues.size())
  {
    this->IsosurfaceValues.resize(i + 1, 0.0);
  }
  else if (this->IsosurfaceValues[i] == value)
  {
    return;
  }
  this->IsosurfaceValues[i] = value;
  this->Modified();
}

void vtkPsiVolumeMapper::SetNumberOfIsosurfaceOpacities(int n)
{
  n = std::max(0, n);
  if (static_cast<size_t>(n) != this->IsosurfaceOpacities.size())
  {
    this->IsosurfaceOpacities.resize(n, this->IsosurfaceOpacity);
    this->Modified();
  }
}

void vtkPsiVolumeMapper::SetIsosurfaceOpacityValue(int i, double opacity)
{
  if (i < 0)
  {
    return;
  }
  if (static_cast<size_t>(i) >= this->IsosurfaceOpacities.size())
  {
    this->IsosurfaceOpacities.resize(i + 1, this->IsosurfaceOpacity);
  }
  else if (this->IsosurfaceOpacities[i] == opacity)
  {
    return;
  }
  this->IsosurfaceOpacities[i] = opacity;
  this->Modified();
}

void vtkPsiVolumeMapper::SetIsosurfaceOpacities(const std::vector<double>& opacities)
{
  if (opacities != this->IsosurfaceOpacities)
  {
    this->IsosurfaceOpacities = opacities;
    this->Modified();
  }
}

double vtkPsiVolumeMapper::GetIsosurfaceValue(int i) const
{
  return i >= 0 && static_cast<size_t>(i) < this->IsosurfaceValues.size()
    ? this->IsosurfaceValues[i]
    : 0.0;
}

void vtkPsiVolumeMapper::SetIsosurfaceValues(const std::vector<double>& values)
{
  if (values != this->IsosurfaceValues)
  {
    this->IsosurfaceValues = values;
    this->Modified();
  }
}

const char* vtkPsiVolumeMapper::GetIntegrationMethodName(int method)
{
  switch (method)
  {
    case AVERAGE:
      return "Average";
    case PARTIAL_PRE_INTEGRATION:
    case LINEAR_EXACT:
    case AVERAGE_OPACITY:
    case LINEAR_LUMINANCE_AVERAGE_OPACITY:
    case LINEAR_OPACITY_IMPROVED:
    case FULL_PRE_INTEGRATION:
      return psi::MethodName(static_cast<psi::Method>(method));
    default:
      return "Unknown";
  }
}

void vtkPsiVolumeMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Impl->Release(win);
  this->Superclass::ReleaseGraphicsResources(win);
}

void vtkPsiVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  const auto t0 = Clock::now();
  Internals& I = *this->Impl;
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkUnstructuredGridBase* input = this->GetInput();
  if (!renWin || !input)
  {
    return;
  }
  if (I.Context && I.Context != renWin)
  {
    I.Release(I.Context);
  }
  I.Context = renWin;

  // ---- 1. Mesh: gathered and uploaded once, again only when the data or array changes.
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(input, this->ScalarMode,
    this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (input->GetNumberOfCells() == 0)
  {
    this->ResetStatistics();
    return; // nothing to draw; an empty grid is not an error
  }
  if (!scalars)
  {
    vtkErrorMacro("Psi Volume needs a scalar array to color by: choose a point or cell array "
                  "(Coloring) for this representation.");
    return;
  }
  const std::string arrayKey = std::string(scalars->GetName() ? scalars->GetName() : "") + "|" +
    std::to_string(cellFlag) + "|" + std::to_string(this->ScalarMode);
  const vtkMTimeType meshTime = std::max(input->GetMTime(), scalars->GetMTime());
  if (!I.MeshOnGPU || meshTime != I.MeshTime || input != I.MeshInput ||
    arrayKey != I.MeshArrayKey)
  {
    I.Mesh = GatherMesh(input, scalars, cellFlag == 1);
    I.MeshTime = meshTime;
    I.MeshInput = input;
    I.MeshArrayKey = arrayKey;
    this->NumberOfSkippedCells = I.Mesh.NonTetCells + I.Mesh.NonFiniteTets;
    if (I.Mesh.NonTetCells && I.Mesh.Tets.empty() && !I.Mesh.NonFiniteTets)
    {
      vtkWarningMacro("Psi Volume: the input has no volume cells (" << I.Mesh.NonTetCells
                                                                    << " surface, line or vertex "
                                                                       "cells): nothing to "
                                                                       "volume-render. Use a "
                                                                       "Surface representation.");
    }
    else if (I.Mesh.NonTetCells)
    {
      vtkWarningMacro("Psi Volume skipped " << I.Mesh.NonTetCells
                                            << " cells that are not linear tetrahedra (e.g. "
                                               "surface cells mixed into the mesh, or input "
                                               "given to the mapper without tetrahedralization).");
    }
    if (I.Mesh.NonFiniteTets)
    {
      vtkWarningMacro("Psi Volume skipped " << I.Mesh.NonFiniteTets
                                            << " tetrahedra with NaN or infinite scalars.");
    }
    const size_t ntets = I.Mesh.Tets.size() / 4;
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    if (I.Mesh.Points4.size() / 4 > static_cast<size_t>(maxTexels) || ntets > 0xffffffffu)
    {
      vtkErrorMacro("Psi Volume: mesh too large for this GPU (" << I.Mesh.Points4.size() / 4
                                                                << " points; the limit is "
                                                                << maxTexels << ").");
      I.Mesh = MeshData();
    }
    this->NumberOfTetrahedra = static_cast<vtkIdType>(I.Mesh.Tets.size() / 4);
    I.Centroids = psi::ComputeCentroids(
      I.Mesh.Points4.data(), I.Mesh.Tets.data(), I.Mesh.Tets.size() / 4);
    I.Neighbors.clear();
    I.PreValid = false;
    if (!I.MeshOnGPU)
    {
      glGenBuffers(1, &I.TetBuffer);
      glGenBuffers(1, &I.IndexBuffer);
      glGenVertexArrays(1, &I.VAO);
    }
    I.PointsBuffer->Upload(I.Mesh.Points4.empty() ? std::vector<float>(4, 0.f) : I.Mesh.Points4,
      vtkOpenGLBufferObject::TextureBuffer);
    I.PointsTexture->SetContext(renWin);
    I.PointsTexture->CreateTextureBuffer(
      static_cast<unsigned int>(std::max<size_t>(I.Mesh.Points4.size() / 4, 1)), 4, VTK_FLOAT,
      I.PointsBuffer);
    glBindBuffer(GL_ARRAY_BUFFER, I.TetBuffer);
    glBufferData(GL_ARRAY_BUFFER, I.Mesh.Tets.size() * sizeof(uint32_t), I.Mesh.Tets.data(),
      GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    I.MeshOnGPU = true;
    I.OrderOnGPU = false;
    I.GradientsOnGPU = false;
  }
  const size_t ntets = I.Mesh.Tets.size() / 4;
  if (ntets == 0)
  {
    return;
  }

  // ---- 2. Camera: model (shifted) -> view and view -> clip matrices.
  vtkOpenGLCamera* cam = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
  vtkMatrix4x4 *wcvc, *vcdc, *wcdc;
  vtkMatrix3x3* norms;
  cam->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc); // transposed (OpenGL order)
  double shift[16];
  vtkMatrix4x4::Identity(shift);
  shift[3] = I.Mesh.Shift[0];
  shift[7] = I.Mesh.Shift[1];
  shift[11] = I.Mesh.Shift[2];
  double view[16], modelShift[16], mcvc[16];
  vtkMatrix4x4::Transpose(wcvc->GetData(), view);
  Multiply(vol->GetMatrix()->GetData(), shift, modelShift);
  Multiply(view, modelShift, mcvc);
  const bool parallel = cam->GetParallelProjection() != 0;

  // ---- 3. Visibility order, redone only when the view changes (HAPT §3.1, centroid sort).
  std::array<double, 16> mcvcKey;
  std::copy(mcvc, mcvc + 16, mcvcKey.begin());
  if (!I.OrderOnGPU || mcvcKey != I.SortedMCVC || parallel != I.SortedParallel ||
    I.SortedMethod != this->SortMethod)
  {
    const auto ts = Clock::now();
    double inv[16];
    vtkMatrix4x4::Invert(mcvc, inv);
    double eye[3];
    if (parallel)
    {
      // view direction (0, 0, -1) in model coordinates
      eye[0] = -inv[2];
      eye[1] = -inv[6];
      eye[2] = -inv[10];
    }
    else
    {
      eye[0] = inv[3] / inv[15];
      eye[1] = inv[7] / inv[15];
      eye[2] = inv[11] / inv[15];
    }
    if (this->SortMethod == MPVONC)
    {
      if (I.Neighbors.empty())
      {
        psi::ComputeTetNeighbors(
          I.Mesh.Tets.data(), ntets, I.Mesh.Points4.size() / 4, I.Neighbors);
      }
      const psi::MPVONCResult r = psi::SortMPVONC(I.Mesh.Points4.data(), I.Mesh.Tets.data(),
        ntets, I.Neighbors.data(), eye, parallel, I.Order);
      this->LastSortCycles = static_cast<vtkIdType>(r.CyclesBroken);
    }
    else
    {
      psi::SortBackToFront(I.Centroids, eye, parallel, I.Order);
      this->LastSortCycles = 0;
    }
    I.SortedMethod = this->SortMethod;
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, I.IndexBuffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, I.Order.size() * sizeof(uint32_t), I.Order.data(),
      GL_STREAM_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    I.SortedMCVC = mcvcKey;
    I.SortedParallel = parallel;
    I.OrderOnGPU = true;
    this->LastSortSeconds = SecondsSince(ts);
  }

  // ---- 4. Transfer function table and, for partial pre-integration, the Psi table.
  vtkVolumeProperty* property = vol->GetProperty();
  if (property->GetMTime() > I.TransferTime || I.TransferRange[0] != I.Mesh.ScalarRange[0] ||
    I.TransferRange[1] != I.Mesh.ScalarRange[1] ||
    I.TransferSamples != this->TransferFunctionSamples)
  {
    const psi::TransferFunctionTable tf =
      psi::SampleTransferFunction(property, I.Mesh.ScalarRange, this->TransferFunctionSamples);
    // ParaView touches the property's MTime when representation properties change; only a change
    // of the sampled content costs an upload (and, for full pre-integration, a table rebuild).
    if (tf.Rgba != I.Transfer.Rgba || !I.TransferTexture->GetHandle())
    {
      I.TransferTexture->SetContext(renWin);
      I.TransferTexture->Create2DFromRaw(
        tf.Size, 1, 4, VTK_FLOAT, const_cast<float*>(tf.Rgba.data()));
      I.TransferTexture->SetMinificationFilter(vtkTextureObject::Linear);
      I.TransferTexture->SetMagnificationFilter(vtkTextureObject::Linear);
      I.TransferTexture->SetWrapS(vtkTextureObject::ClampToEdge);
      I.TransferTexture->SetWrapT(vtkTextureObject::ClampToEdge);
      I.Transfer = tf;
      ++I.TransferVersion;
      std::vector<float> prefix(tf.Size);
      float count = 0;
      for (int i = 0; i < tf.Size; ++i)
      {
        count += tf.Rgba[4 * static_cast<size_t>(i) + 3] > 0 ? 1.0f : 0.0f;
        prefix[i] = count;
      }
      I.TransferHasZeroOpacity = count < tf.Size - 1;
      I.OpacityPrefixTexture->SetContext(renWin);
      I.OpacityPrefixTexture->Create2DFromRaw(tf.Size, 1, 1, VTK_FLOAT, prefix.data());
    }
    I.TransferTime = property->GetMTime();
    I.TransferRange[0] = I.Mesh.ScalarRange[0];
    I.TransferRange[1] = I.Mesh.ScalarRange[1];
    I.TransferSamples = this->TransferFunctionSamples;
  }
  const bool needPre = this->IntegrationMethod == FULL_PRE_INTEGRATION;
  const bool needPsi = this->IntegrationMethod == PARTIAL_PRE_INTEGRATION;
  if (needPsi && I.PsiSize == 0)
  {
    const psi::PsiTable& table = psi::GetDefaultPsiTable();
    I.PsiTexture->SetContext(renWin);
    I.PsiTexture->Create2DFromRaw(
      table.N, table.N, 1, VTK_FLOAT, const_cast<float*>(table.Values.data()));
    I.PsiTexture->SetMinificationFilter(vtkTextureObject::Linear);
    I.PsiTexture->SetMagnificationFilter(vtkTextureObject::Linear);
    I.PsiTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    I.PsiTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    I.PsiSize = table.N;
  }
  if (needPre &&
    (!I.PreValid || I.PreVersion != I.TransferVersion ||
      I.PreTable.MaxLength != I.Mesh.MaxEdgeLength))
  {
    // Roettger's table belongs to one transfer function: rebuilt on every edit (timed).
    I.PreTable =
      psi::BuildPreIntegrationTable(I.Transfer, psi::GetDefaultPsiTable(), I.Mesh.MaxEdgeLength);
    this->LastPreIntegrationSeconds = I.PreTable.BuildSeconds;
    I.PreTexture->SetContext(renWin);
    I.PreTexture->Create3DFromRaw(I.PreTable.ScalarSamples, I.PreTable.ScalarSamples,
      I.PreTable.LengthSamples, 4, VTK_FLOAT, I.PreTable.Rgba.data());
    I.PreTexture->SetMinificationFilter(vtkTextureObject::Linear);
    I.PreTexture->SetMagnificationFilter(vtkTextureObject::Linear);
    I.PreTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    I.PreTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    I.PreTexture->SetWrapR(vtkTextureObject::ClampToEdge);
    I.PreTable.Rgba.clear();
    I.PreTable.Rgba.shrink_to_fit();
    I.PreVersion = I.TransferVersion;
    I.PreValid = true;
  }

  // ---- 4b. Isosurfaces and adaptive sampling: only what is switched on costs anything.
  // (value, opacity) of each finite isovalue, ascending; a repeated value keeps its first entry.
  std::vector<std::pair<float, float>> isoList;
  for (size_t i = 0; i < this->IsosurfaceValues.size(); ++i)
  {
    const double v = this->IsosurfaceValues[i];
    const double o = i < this->IsosurfaceOpacities.size() ? this->IsosurfaceOpacities[i]
                                                           : this->IsosurfaceOpacity;
    if (std::isfinite(v) && std::abs(v) < 1e37)
    {
      isoList.emplace_back(static_cast<float>(v),
        static_cast<float>(std::isfinite(o) ? std::min(1.0, std::max(0.0, o)) : 1.0));
    }
  }
  std::stable_sort(isoList.begin(), isoList.end(),
    [](const std::pair<float, float>& a, const std::pair<float, float>& b) {
      return a.first < b.first;
    });
  isoList.erase(std::unique(isoList.begin(), isoList.end(),
                  [](const std::pair<float, float>& a, const std::pair<float, float>& b) {
                    return a.first == b.first;
                  }),
    isoList.end());
  if (isoList.size() > static_cast<size_t>(MaxIsosurfaces))
  {
    vtkWarningMacro("Psi Volume draws at most " << MaxIsosurfaces << " isosurfaces; "
                                                << isoList.size() - MaxIsosurfaces
                                                << " ignored.");
    isoList.resize(MaxIsosurfaces);
  }
  std::vector<float> isoValues, isoOpacities;
  for (const auto& vo : isoList)
  {
    isoValues.push_back(vo.first);
    isoOpacities.push_back(vo.second);
  }
  const bool iso = !isoValues.empty();
  const bool smoothIso = iso && this->IsosurfaceShading == ISO_SMOOTH;
  if (smoothIso && !I.GradientsOnGPU)
  {
    I.GradientBuffer->Upload(PointGradients(I.Mesh), vtkOpenGLBufferObject::TextureBuffer);
    I.GradientTexture->SetContext(renWin);
    I.GradientTexture->CreateTextureBuffer(
      static_cast<unsigned int>(std::max<size_t>(I.Mesh.Points4.size() / 4, 1)), 4, VTK_FLOAT,
      I.GradientBuffer);
    I.GradientsOnGPU = true;
  }
  std::vector<float> tfNodes;
  if (this->AdaptiveSampling != ADAPTIVE_OFF)
  {
    tfNodes = TransferFunctionKinks(property, I.Mesh.ScalarRange);
  }
  const bool adaptive = this->AdaptiveSampling == ADAPTIVE_ON ||
    (this->AdaptiveSampling == ADAPTIVE_AUTO && !tfNodes.empty());
  this->LastUsedAdaptiveSampling = adaptive;
  this->LastNumberOfAdaptiveNodes = adaptive ? static_cast<int>(tfNodes.size()) : 0;

  // ---- 5. Frame buffers: the scene's depth, and a float target for the volume.
  int w, h, x0, y0;
  ren->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  if (w <= 0 || h <= 0)
  {
    return;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  I.DepthTexture->SetContext(renWin);
  I.DepthSampleTexture->SetContext(renWin);
  if (I.Size[0] != w || I.Size[1] != h || !I.Framebuffer)
  {
    I.DepthTexture->AllocateDepth(w, h, vtkTextureObject::Float32);
    I.DepthSampleTexture->AllocateDepth(w, h, vtkTextureObject::Float32);
    ostate->PushFramebufferBindings();
    if (!I.Framebuffer)
    {
      I.Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      I.Framebuffer->SetContext(renWin);
      I.Framebuffer->PopulateFramebuffer(w, h, true, 1, VTK_FLOAT, false, 0, 0);
    }
    I.Framebuffer->Bind();
    I.Framebuffer->Resize(w, h);
    I.Framebuffer->AddDepthAttachment(I.DepthTexture);
    ostate->PopFramebufferBindings();
    I.Size[0] = w;
    I.Size[1] = h;
  }
  // The scene's depth, read from the framebuffer bound for reading (the one being rendered).
  I.DepthTexture->Activate();
  I.DepthTexture->CopyFromFrameBuffer(x0, y0, 0, 0, w, h);
  I.DepthTexture->Deactivate();

  // ---- 6. Shader program for this feature set (cached by VTK's shader cache). Only what the
  // scene calls for is compiled in: the near-plane path only when the near plane cuts the mesh.
  double proj[16], invProj[16];
  vtkMatrix4x4::Transpose(vcdc->GetData(), proj);
  vtkMatrix4x4::Invert(proj, invProj);
  const double nearZ = (invProj[2] * -1 + invProj[3]) / (invProj[14] * -1 + invProj[15]);
  bool nearClip = false;
  for (int corner = 0; corner < 8 && !nearClip; ++corner)
  {
    const double* b = I.Mesh.Bounds;
    const double p[4] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)],
      1 };
    const double z = mcvc[8] * p[0] + mcvc[9] * p[1] + mcvc[10] * p[2] + mcvc[11];
    nearClip = z > nearZ;
  }
  this->LastUsedNearPlaneClipping = nearClip;
  const bool opaqueClip = OpaqueGeometryInside(ren, vol);
  this->LastUsedOpaqueClipping = opaqueClip;
  const bool sampleDepth = nearClip || opaqueClip;
  if (sampleDepth)
  {
    I.DepthSampleTexture->Activate();
    I.DepthSampleTexture->CopyFromFrameBuffer(x0, y0, 0, 0, w, h);
  }
  // The program is composed from the feature set by psi::ComposeShaders (PsiShaderComposer.h);
  // the marching-tetrahedra output budget is counted from the same features.
  psi::ShaderFeatures features;
  features.Method = this->IntegrationMethod;
  features.OpaqueClip = opaqueClip;
  features.ExactSegments = !parallel && this->ExactPerspectiveSegments;
  features.NearClip = nearClip;
  features.MaxAdaptiveNodes = MaxAdaptiveNodes;
  constexpr int maxLights = 8; // also bounds the lights uploaded below
  features.MaxLights = maxLights;
  bool isoTriangles = false;
  if (iso)
  {
    features.IsoCount = static_cast<int>(isoValues.size());
    features.IsoSmooth = smoothIso;
    if (this->IsosurfaceMethod == ISO_MARCHING_TETRAHEDRA ||
      (this->IsosurfaceMethod == ISO_AUTO && this->EarlyDiscard && I.TransferHasZeroOpacity))
    {
      GLint maxVertices = 0, maxComponents = 0;
      glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES, &maxVertices);
      glGetIntegerv(GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS, &maxComponents);
      psi::ShaderFeatures triangles = features;
      triangles.IsoTriangles = true;
      isoTriangles = psi::FitsGeometryOutputLimits(triangles, maxVertices, maxComponents);
    }
    features.IsoTriangles = isoTriangles;
  }
  this->LastUsedIsosurfaceMethod =
    !iso ? -1 : isoTriangles ? ISO_MARCHING_TETRAHEDRA : ISO_PER_FRAGMENT;
  // Early discard only when the opacity function has zero regions, and not with per-fragment
  // isosurfaces (which are visible where the volume is transparent; marching tetrahedra still
  // emit the surfaces of a cell whose volume pieces are dropped).
  const bool earlyDiscard =
    this->EarlyDiscard && I.TransferHasZeroOpacity && (!iso || isoTriangles);
  this->LastUsedEarlyDiscard = earlyDiscard;
  features.EarlyDiscard = earlyDiscard;
  features.Adaptive = adaptive;
  this->LastFeatureDefines = features.Defines();
  const std::string key = features.Key();
  if (!I.Program || I.ProgramKey != key)
  {
    ++this->NumberOfProgramBuilds;
    psi::ShaderSources src;
    try
    {
      src = psi::ComposeShaders(features, IntegratorSource(this->IntegrationMethod));
    }
    catch (const std::exception& e) // a shader template error (TestShaderComposition)
    {
      vtkErrorMacro("Psi Volume: " << e.what());
      I.Program = nullptr;
      return;
    }
    I.Program = renWin->GetShaderCache()->ReadyShaderProgram(
      src.Vertex.c_str(), src.Fragment.c_str(), src.Geometry.c_str());
    I.ProgramKey = key;
    if (!I.Program)
    {
      vtkErrorMacro("Psi Volume: the shader program failed to compile (see above).");
      return;
    }
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(I.Program);
  }
  vtkShaderProgram* prog = I.Program;

  vtkNew<vtkMatrix4x4> mcvcGL, dcvcGL;
  vtkMatrix4x4::Transpose(mcvc, mcvcGL->GetData()); // to OpenGL (column-major) order
  vtkMatrix4x4::Transpose(invProj, dcvcGL->GetData());
  prog->SetUniformf("nearZ", static_cast<float>(nearZ));
  prog->SetUniformi("parallelProjection", parallel ? 1 : 0);
  prog->SetUniformMatrix("MCVCMatrix", mcvcGL);
  prog->SetUniformMatrix("VCDCMatrix", vcdc);
  prog->SetUniformMatrix("DCVCMatrix", dcvcGL);
  prog->SetUniform1iv("classTable", 81, I.ClassTable.data());
  I.PointsTexture->Activate();
  prog->SetUniformi("points", I.PointsTexture->GetTextureUnit());
  I.TransferTexture->Activate();
  prog->SetUniformi("transferFunction", I.TransferTexture->GetTextureUnit());
  const double n = I.TransferSamples, r0 = I.TransferRange[0], r1 = I.TransferRange[1];
  const double scale = (n - 1) / (n * (r1 - r0));
  const float tfScaleShift[2] = { static_cast<float>(scale),
    static_cast<float>(0.5 / n - r0 * scale) };
  prog->SetUniform2f("tfScaleShift", tfScaleShift);
  if (earlyDiscard)
  {
    I.OpacityPrefixTexture->Activate();
    prog->SetUniformi("opacityPrefix", I.OpacityPrefixTexture->GetTextureUnit());
    // scalar -> sample index: (s - r0) (N - 1) / (r1 - r0)
    const float index[2] = { static_cast<float>((n - 1) / (r1 - r0)),
      static_cast<float>(-r0 * (n - 1) / (r1 - r0)) };
    prog->SetUniform2f("tfIndexScaleShift", index);
    prog->SetUniformi("tfSamples", static_cast<int>(n));
  }
  prog->SetUniformf("unitDistance",
    static_cast<float>(std::max(property->GetScalarOpacityUnitDistance(0), 1e-30)));
  if (needPre)
  {
    I.PreTexture->Activate();
    prog->SetUniformi("preIntegrated", I.PreTexture->GetTextureUnit());
    const double ns = I.PreTable.ScalarSamples, nd = I.PreTable.LengthSamples;
    const double pr0 = I.PreTable.Range[0], pr1 = I.PreTable.Range[1];
    const double ss = (ns - 1) / (ns * (pr1 - pr0));
    const float preScalar[2] = { static_cast<float>(ss), static_cast<float>(0.5 / ns - pr0 * ss) };
    const float preLength[2] = { static_cast<float>((nd - 1) / (nd * I.PreTable.MaxLength)),
      static_cast<float>(0.5 / nd) };
    prog->SetUniform2f("preScalarScaleShift", preScalar);
    prog->SetUniform2f("preLengthScaleShift", preLength);
  }
  if (needPsi)
  {
    I.PsiTexture->Activate();
    prog->SetUniformi("psiTable", I.PsiTexture->GetTextureUnit());
    const float psiScaleShift[2] = { static_cast<float>((I.PsiSize - 1.0) / I.PsiSize),
      static_cast<float>(0.5 / I.PsiSize) };
    prog->SetUniform2f("psiScaleShift", psiScaleShift);
  }
  if (sampleDepth)
  {
    prog->SetUniformi("sceneDepth", I.DepthSampleTexture->GetTextureUnit());
  }
  const float viewport[2] = { static_cast<float>(w), static_cast<float>(h) };
  prog->SetUniform2f("viewportSize", viewport);
  if (smoothIso)
  {
    I.GradientTexture->Activate();
    prog->SetUniformi("pointGradients", I.GradientTexture->GetTextureUnit());
    // Gradients are covectors: model -> view by the inverse transpose of the linear part.
    vtkNew<vtkMatrix3x3> nm;
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        nm->SetElement(r, c, mcvc[4 * r + c]);
      }
    }
    // (A^-1)^T in OpenGL's column-major order is A^-1 in VTK's row-major order.
    nm->Invert();
    prog->SetUniformMatrix("normalMatrix", nm);
  }
  if (iso)
  {
    const int niso = static_cast<int>(isoValues.size());
    std::vector<float> colors(3 * niso);
    for (int i = 0; i < niso; ++i)
    {
      double rgba[4];
      EvaluateTransfer(property, isoValues[i], rgba);
      for (int k = 0; k < 3; ++k)
      {
        colors[3 * i + k] = static_cast<float>(
          this->IsosurfaceUseColorMap ? rgba[k] : std::min(1.0, std::max(0.0, this->IsosurfaceColor[k])));
      }
    }
    prog->SetUniform1fv("isoValues", niso, isoValues.data());
    prog->SetUniform3fv("isoColors", niso, reinterpret_cast<const float(*)[3]>(colors.data()));
    prog->SetUniform1fv("isoOpacities", niso, isoOpacities.data());
    prog->SetUniformi("isoLighting", this->IsosurfaceLighting ? 1 : 0);
    // The renderer's lights as VTK's surface shaders see them (directional: focal point minus
    // position, in view coordinates; diffuse color times intensity).
    std::vector<float> dirs, cols;
    vtkLightCollection* lights = ren->GetLights();
    vtkCollectionSimpleIterator lit;
    lights->InitTraversal(lit);
    double rot[9];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        rot[3 * r + c] = view[4 * r + c];
      }
    }
    while (vtkLight* light = lights->GetNextLight(lit))
    {
      if (!light->GetSwitch() || light->GetIntensity() <= 0 ||
        static_cast<int>(dirs.size()) >= 3 * maxLights)
      {
        continue;
      }
      const double* fp = light->GetTransformedFocalPoint();
      const double* lp = light->GetTransformedPosition();
      double d[3] = { fp[0] - lp[0], fp[1] - lp[1], fp[2] - lp[2] };
      double dv[3];
      for (int r = 0; r < 3; ++r)
      {
        dv[r] = rot[3 * r] * d[0] + rot[3 * r + 1] * d[1] + rot[3 * r + 2] * d[2];
      }
      const double len = std::sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]);
      if (!(len > 0))
      {
        continue;
      }
      const double* dc = light->GetDiffuseColor();
      for (int k = 0; k < 3; ++k)
      {
        dirs.push_back(static_cast<float>(dv[k] / len));
        cols.push_back(static_cast<float>(dc[k] * light->GetIntensity()));
      }
    }
    const int nl = static_cast<int>(dirs.size() / 3);
    prog->SetUniformi("lightCount", nl);
    if (nl > 0)
    {
      prog->SetUniform3fv("lightDirVC", nl, reinterpret_cast<const float(*)[3]>(dirs.data()));
      prog->SetUniform3fv("lightColor", nl, reinterpret_cast<const float(*)[3]>(cols.data()));
    }
  }
  if (adaptive)
  {
    const int nn = static_cast<int>(tfNodes.size());
    prog->SetUniformi("tfNodeCount", nn);
    if (nn > 0)
    {
      prog->SetUniform1fv("tfNodes", nn, tfNodes.data());
    }
  }

  // ---- 7. Draw back to front into the float target; premultiplied "over" blending.
  {
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cull(ostate, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglClearColor clearColor(ostate);

    ostate->PushFramebufferBindings();
    I.Framebuffer->Bind();
    I.Framebuffer->ActivateDrawBuffer(0);
    ostate->vtkglViewport(0, 0, w, h);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglClearColor(0, 0, 0, 0);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    ostate->vtkglEnable(GL_DEPTH_TEST); // against the scene's opaque geometry
    ostate->vtkglDepthFunc(GL_LESS);
    ostate->vtkglDepthMask(GL_FALSE);
    ostate->vtkglDisable(GL_CULL_FACE);
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

    glBindVertexArray(I.VAO);
    glBindBuffer(GL_ARRAY_BUFFER, I.TetBuffer);
    const GLint loc = glGetAttribLocation(prog->GetHandle(), "tetPointIds");
    glEnableVertexAttribArray(loc);
    glVertexAttribIPointer(loc, 4, GL_UNSIGNED_INT, 0, nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, I.IndexBuffer);
    // Streamed in chunks so that no single draw call is unbounded (huge meshes).
    const size_t chunk = size_t(1) << 22;
    for (size_t first = 0; first < ntets; first += chunk)
    {
      const size_t count = std::min(chunk, ntets - first);
      glDrawElements(GL_POINTS, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(first * sizeof(uint32_t)));
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    ostate->PopFramebufferBindings();

    // ---- 8. Composite the volume image (premultiplied) over the scene.
    ostate->vtkglViewport(x0, y0, w, h);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    if (!I.Composite)
    {
      I.Composite.reset(new vtkOpenGLQuadHelper(renWin, nullptr, PsiCompositeFS, ""));
    }
    else
    {
      renWin->GetShaderCache()->ReadyShaderProgram(I.Composite->Program);
    }
    if (I.Composite->Program)
    {
      vtkTextureObject* color = I.Framebuffer->GetColorAttachmentAsTextureObject(0);
      color->Activate();
      I.Composite->Program->SetUniformi("volumeImage", color->GetTextureUnit());
      I.Composite->Render();
      color->Deactivate();
    }
  }
  I.PointsTexture->Deactivate();
  I.TransferTexture->Deactivate();
  if (earlyDiscard)
  {
    I.OpacityPrefixTexture->Deactivate();
  }
  if (smoothIso)
  {
    I.GradientTexture->Deactivate();
  }
  if (sampleDepth)
  {
    I.DepthSampleTexture->Deactivate();
  }
  if (needPsi)
  {
    I.PsiTexture->Deactivate();
  }
  if (needPre)
  {
    I.PreTexture->Deactivate();
  }
  this->LastRenderSeconds = SecondsSince(t0);
}

void vtkPsiVolumeMapper::ResetStatistics()
{
  this->NumberOfTetrahedra = 0;
  this->NumberOfSkippedCells = 0;
  this->LastSortSeconds = 0;
  this->LastRenderSeconds = 0;
}

void vtkPsiVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegrationMethod: " << GetIntegrationMethodName(this->IntegrationMethod)
     << "\n";
  os << indent << "TransferFunctionSamples: " << this->TransferFunctionSamples << "\n";
  os << indent << "IsosurfaceMethod: "
     << (this->IsosurfaceMethod == ISO_MARCHING_TETRAHEDRA ? "marching tetrahedra"
            : this->IsosurfaceMethod == ISO_PER_FRAGMENT    ? "per fragment"
                                                            : "auto")
     << ", shading: " << (this->IsosurfaceShading == ISO_SMOOTH ? "smooth" : "flat") << "\n";
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "NumberOfSkippedCells: " << this->NumberOfSkippedCells << "\n";
}
