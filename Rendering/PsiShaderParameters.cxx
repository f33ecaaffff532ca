#include "PsiShaderParameters.h"

#include "PsiPixelRays.h"
#include "PsiTetMesh.h"
#include "PsiTransferFunctionAnalysis.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLCamera.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cmath>
#include <vector>

PsiFrameCamera PsiFrameCamera::FromRenderer(vtkRenderer* ren, vtkVolume* vol, const double shift[3])
{
  PsiFrameCamera c;
  vtkOpenGLCamera* cam = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
  vtkMatrix4x4 *wcvc, *vcdc, *wcdc;
  vtkMatrix3x3* norms;
  cam->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc); // transposed (OpenGL order)
  double shiftMatrix[16], modelShift[16];
  vtkMatrix4x4::Identity(shiftMatrix);
  shiftMatrix[3] = shift[0];
  shiftMatrix[7] = shift[1];
  shiftMatrix[11] = shift[2];
  vtkMatrix4x4::Transpose(wcvc->GetData(), c.View);
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix()->GetData(), shiftMatrix, modelShift);
  vtkMatrix4x4::Multiply4x4(c.View, modelShift, c.MCVC);
  vtkMatrix4x4::Transpose(vcdc->GetData(), c.VCDC);
  vtkMatrix4x4::Invert(c.VCDC, c.DCVC);
  c.Parallel = cam->GetParallelProjection() != 0;
  const double* inv = c.DCVC; // the near plane is z = -1 in clip coordinates
  c.NearZ = (inv[2] * -1 + inv[3]) / (inv[14] * -1 + inv[15]);
  return c;
}

bool PsiFrameCamera::NearPlaneCuts(const double b[6]) const
{
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[3] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)] };
    const double z =
      this->MCVC[8] * p[0] + this->MCVC[9] * p[1] + this->MCVC[10] * p[2] + this->MCVC[11];
    if (z > this->NearZ)
    {
      return true;
    }
  }
  return false;
}

namespace
{
void SetMatrix(vtkShaderProgram* program, const char* name, const double rowMajor[16])
{
  vtkNew<vtkMatrix4x4> m;
  vtkMatrix4x4::Transpose(rowMajor, m->GetData()); // to OpenGL (column-major) order
  program->SetUniformMatrix(name, m);
}

// The renderer's lights as VTK's surface shaders see them: directional, traveling from the
// position to the focal point (view coordinates); diffuse color times intensity.
void SetLightShaderParameters(
  vtkShaderProgram* program, vtkRenderer* ren, const double view[16], int maxLights)
{
  std::vector<float> dirs, cols;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || light->GetIntensity() <= 0 ||
      static_cast<int>(dirs.size()) >= 3 * maxLights)
    {
      continue;
    }
    const double* fp = light->GetTransformedFocalPoint();
    const double* lp = light->GetTransformedPosition();
    const double d[3] = { fp[0] - lp[0], fp[1] - lp[1], fp[2] - lp[2] };
    double dv[3];
    for (int r = 0; r < 3; ++r)
    {
      dv[r] = view[4 * r] * d[0] + view[4 * r + 1] * d[1] + view[4 * r + 2] * d[2];
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
  const int n = static_cast<int>(dirs.size() / 3);
  program->SetUniformi("lightCount", n);
  if (n > 0)
  {
    program->SetUniform3fv("lightDirVC", n, reinterpret_cast<const float(*)[3]>(dirs.data()));
    program->SetUniform3fv("lightColor", n, reinterpret_cast<const float(*)[3]>(cols.data()));
  }
}

// Gradients are covectors: model -> view by the inverse transpose of the linear part, which in
// OpenGL's column-major order is the inverse in VTK's row-major order.
void SetNormalMatrix(vtkShaderProgram* program, const double mcvc[16])
{
  vtkNew<vtkMatrix3x3> nm;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      nm->SetElement(r, c, mcvc[4 * r + c]);
    }
  }
  nm->Invert();
  program->SetUniformMatrix("normalMatrix", nm);
}
} // namespace

void SetCameraShaderParameters(vtkShaderProgram* program, const PsiFrameCamera& camera)
{
  program->SetUniformf("nearZ", static_cast<float>(camera.NearZ));
  program->SetUniformi("parallelProjection", camera.Parallel ? 1 : 0);
  SetMatrix(program, "MCVCMatrix", camera.MCVC);
  SetMatrix(program, "VCDCMatrix", camera.VCDC);
  SetMatrix(program, "DCVCMatrix", camera.DCVC);
}

void SetPixelRayShaderParameters(
  vtkShaderProgram* program, const PsiFrameCamera& camera, const int size[2])
{
  const psi::PixelRays rays = psi::PixelRaysOf(camera.DCVC, camera.Parallel, size[0], size[1]);
  float origin[3][3], step[3][3];
  for (int j = 0; j < 3; ++j)
  {
    for (int k = 0; k < 3; ++k)
    {
      origin[j][k] = static_cast<float>(rays.Origin[j][k]);
      step[j][k] = static_cast<float>(rays.Step[j][k]);
    }
  }
  program->SetUniform3fv("pixelRayOrigin", 3, origin);
  program->SetUniform3fv("pixelRayStep", 3, step);
}

void SetSilhouetteShaderParameters(vtkShaderProgram* program, const int size[2])
{
  const double ndcPerPixel = 4.0 / (static_cast<double>(size[0]) * size[1]);
  program->SetUniformf("coverExtraMax", static_cast<float>(PsiSilhouetteCoverPixels * ndcPerPixel));
}

void SetIsosurfaceShaderParameters(vtkShaderProgram* program, const psi::IsosurfaceList& list,
  const double scalarRange[2], const PsiIsosurfaceStyle& style, vtkVolumeProperty* property,
  vtkRenderer* ren, const PsiFrameCamera& camera)
{
  const int n = list.Count();
  std::vector<float> values(n), colors(3 * n);
  for (int i = 0; i < n; ++i)
  {
    // a value outside the range meets no cell: any fraction outside [0, 1] says so
    values[i] = static_cast<float>(
      std::min(std::max(psi::UnitScalar(scalarRange, list.Values[i]), -1.0), 2.0));
    double rgba[4] = { 1, 1, 1, 1 };
    if (style.ValueColors)
    {
      for (const auto& vc : *style.ValueColors)
      {
        if (vc.first == list.Values[i])
        {
          std::copy(vc.second.begin(), vc.second.end(), rgba);
        }
      }
    }
    else
    {
      psi::EvaluateTransferFunction(property, list.Values[i], rgba);
    }
    for (int k = 0; k < 3; ++k)
    {
      colors[3 * i + k] = static_cast<float>(
        style.UseColorMap ? rgba[k] : std::min(1.0, std::max(0.0, style.Color[k])));
    }
  }
  program->SetUniform1fv("isoValues", n, values.data());
  program->SetUniform3fv("isoColors", n, reinterpret_cast<const float(*)[3]>(colors.data()));
  program->SetUniform1fv("isoOpacities", n, list.Opacities.data());
  program->SetUniformi("isoLighting", style.Lighting ? 1 : 0);
  SetLightShaderParameters(program, ren, camera.View, style.MaxLights);
  if (style.Smooth)
  {
    SetNormalMatrix(program, camera.MCVC);
  }
}
