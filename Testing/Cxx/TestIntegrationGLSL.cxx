// The GLSL integration methods (Shaders/PsiIntegrate*.glsl, compiled exactly as the mapper does)
// evaluated on the GPU path for thousands of segments, read back as floats, and compared with
// the C++ functions (PsiIntegrationMethods) and with the reference of each method's model:
// Moreland's sweeps (Moreland 2004 dissertation Figs. 6.5-6.11) and the hard cases of
// PsiHardCases.h. Every row of psi::IntegrationMethodTable() that needs no pre-integration table
// is run (the harness binds the Psi table only). Needs an X server (xvfb-run).
#include "PsiHardCases.h"
#include "PsiIntegrationMethods.h"
#include "PsiIntegratorInputsFS.h"
#include "PsiIntegratorSources.h"
#include "PsiPartialPreIntegrationTable.h"
#include "PsiReferenceIntegrals.h"
#include "PsiTestCheck.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace
{
// The harness: transfer() returns the front sample for s = 0 and the back sample for s = 1, then
// the shipped integrator inputs (Shaders/PsiIntegratorInputsFS.glsl: the Psi table coordinate,
// the unit distance), then the method's function.
const char* HarnessFS = R"(//VTK::System::Dec
//VTK::Output::Dec
in vec2 texCoord;
uniform sampler2D frontSamples; // rgb luminance, a tau
uniform sampler2D backSamples;
uniform sampler2D lengths;      // r: D
vec4 gFront, gBack;
vec4 transfer(float s) { return s < 0.5 ? gFront : gBack; }
vec4 transferFront(float s) { return transfer(s); }
vec4 transferBack(float s) { return transfer(s); }
//PSI::Integrator::Inputs
//PSI::Integrator::Impl
void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (texCoord.x < -1.0) discard; // keeps the quad helper's texture coordinate attribute alive
  gFront = texelFetch(frontSamples, p, 0);
  gBack = texelFetch(backSamples, p, 0);
  float D = texelFetch(lengths, p, 0).r;
  gl_FragData[0] = integrateSegment(0.0, 1.0, D);
}
)";

struct Case
{
  psi::TFSegment S;
  bool Hard;
  double (*Bound)(psi::Method m, const psi::TFSegment& s) = nullptr; // psitest::HardCase::Bound
};

std::vector<Case> MakeCases()
{
  std::vector<Case> cases;
  const int n = 16;
  for (double D : { 0.001, 0.1, 1.0, 100.0 })
  {
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; j < n; ++j)
      {
        psi::TFSegment s;
        s.af = (i + 0.5) / n;
        s.ab = (j + 0.5) / n;
        s.Lf = { { 0.0, 0.5, 0.2 } };
        s.Lb = { { 1.0, 0.25, 0.7 } };
        s.D = D;
        cases.push_back({ s, false, nullptr });
      }
    }
  }
  for (const psitest::HardCase& h : psitest::HardCases(true))
  {
    cases.push_back({ h.S, true, h.Bound });
  }
  return cases;
}

// Float-vs-double bound on |GLSL - C++| on float-rounded inputs: 2e-6 by default; Linear Exact
// carries the erfc fit's 1.2e-7 relative error through the 1/sqrt(c) prefactor, and methods 5
// and 6 evaluate Psi of a homogeneous segment from float optical depths. A new method starts at
// the default.
double GpuVsCpuBound(psi::Method m)
{
  switch (m)
  {
    case psi::Method::LinearExact:
    case psi::Method::LinearLuminanceAverageOpacity:
    case psi::Method::LinearOpacityImproved:
      return 1e-5;
    default:
      return 2e-6;
  }
}
constexpr double UnitDistance = 1.5;

// Every table row has its GLSL integrator embedded, and every embedded integrator has a row.
void CheckEmbeddedIntegrators()
{
  for (const psi::IntegrationMethodInfo& info : psi::IntegrationMethodTable())
  {
    PSI_CHECK(psi::IntegratorGlslSource(info.GlslName) != nullptr,
      "%s: Shaders/%s.glsl is not embedded", info.Name, info.GlslName);
  }
  for (const std::string& name : psi::IntegratorGlslNames())
  {
    const auto& table = psi::IntegrationMethodTable();
    PSI_CHECK(std::any_of(table.begin(), table.end(),
                [&](const psi::IntegrationMethodInfo& info) { return name == info.GlslName; }),
      "Shaders/%s.glsl has no row in psi::IntegrationMethodTable()", name.c_str());
  }
}

// The GLSL outputs `out` (RGBA per case) of method `info` against its C++ function and the
// reference of its model on the same float inputs; prints the largest differences.
void CompareWithCpp(const psi::IntegrationMethodInfo& info, const std::vector<Case>& cases,
  const std::vector<float>& out, const psi::PartialPreIntegrationTable& table)
{
  const int W = static_cast<int>(cases.size());
  double gpuCpu = 0, gpuRef = 0, cpuRef = 0;
  int nonFinite = 0, outOfBound = 0;
  for (int i = 0; i < W; ++i)
  {
    // The GPU sees float inputs (alpha = 1 - 1e-6 is off by 1% in 1 - alpha as a float): the
    // C++ side gets the same rounded inputs, so the comparison measures the formulas.
    psi::TFSegment rounded = cases[i].S;
    for (int k = 0; k < 3; ++k)
    {
      rounded.Lf[k] = static_cast<float>(rounded.Lf[k]);
      rounded.Lb[k] = static_cast<float>(rounded.Lb[k]);
    }
    rounded.af = static_cast<float>(rounded.af);
    rounded.ab = static_cast<float>(rounded.ab);
    rounded.D = static_cast<float>(rounded.D);
    const psi::Rgba cpu = info.Integrate(rounded, &table);
    const psi::Rgba ref = psi::IntegrateReferenceFor(info.Id, rounded);
    // a hard case's own bound on the method, beside the float rounding allowed against C++
    const double own = cases[i].Bound ? cases[i].Bound(info.Id, rounded) : -1.0;
    for (int k = 0; k < 4; ++k)
    {
      const double g = out[4 * i + k];
      if (!std::isfinite(g))
      {
        ++nonFinite;
        continue;
      }
      gpuCpu = std::max(gpuCpu, std::abs(g - cpu[k]));
      gpuRef = std::max(gpuRef, std::abs(g - ref[k]));
      cpuRef = std::max(cpuRef, std::abs(cpu[k] - ref[k]));
      outOfBound += own >= 0 && !(std::abs(g - ref[k]) <= own + GpuVsCpuBound(info.Id));
    }
  }
  std::printf("%-34s %12.2e %12.2e %12.2e\n", info.Name, gpuCpu, gpuRef, cpuRef);
  PSI_CHECK(nonFinite == 0, "%s: %d non-finite GLSL outputs", info.Name, nonFinite);
  PSI_CHECK(outOfBound == 0,
    "%s: %d GLSL outputs of hard cases beyond the case's bound of the "
    "reference",
    info.Name, outOfBound);
  PSI_CHECK(gpuCpu < GpuVsCpuBound(info.Id), "%s: GLSL differs from C++ by %g", info.Name, gpuCpu);
}
} // namespace

int main()
{
  vtkNew<vtkRenderWindow> rw;
  rw->SetSize(8, 8);
  rw->SetOffScreenRendering(1);
  rw->Render();
  vtkOpenGLRenderWindow* win = vtkOpenGLRenderWindow::SafeDownCast(rw);
  // A unit distance other than 1 (ScalarOpacityUnitDistance), so that each method's use of it
  // is compared with the C++ version's.
  std::vector<Case> cases = MakeCases();
  for (Case& c : cases)
  {
    c.S.unit = UnitDistance;
  }
  const int W = static_cast<int>(cases.size());
  std::vector<float> front(4 * W), back(4 * W), len(4 * W, 0.0f);
  for (int i = 0; i < W; ++i)
  {
    const psi::TFSegment& s = cases[i].S;
    for (int k = 0; k < 3; ++k)
    {
      front[4 * i + k] = static_cast<float>(s.Lf[k]);
      back[4 * i + k] = static_cast<float>(s.Lb[k]);
    }
    front[4 * i + 3] = static_cast<float>(s.af / s.unit);
    back[4 * i + 3] = static_cast<float>(s.ab / s.unit);
    len[4 * i] = static_cast<float>(s.D);
  }
  auto texture = [&](std::vector<float>& data, int comps)
  {
    vtkNew<vtkTextureObject> t;
    t->SetContext(win);
    t->Create2DFromRaw(W, 1, comps, VTK_FLOAT, data.data());
    return t;
  };
  vtkSmartPointer<vtkTextureObject> tf = texture(front, 4), tb = texture(back, 4),
                                    tl = texture(len, 4);
  const psi::PartialPreIntegrationTable& table = psi::GetDefaultPsiTable();
  vtkNew<vtkTextureObject> psiTex;
  psiTex->SetContext(win);
  psiTex->Create2DFromRaw(table.N, table.N, 1, VTK_FLOAT, const_cast<float*>(table.Values.data()));
  psiTex->SetMinificationFilter(vtkTextureObject::Linear);
  psiTex->SetMagnificationFilter(vtkTextureObject::Linear);
  psiTex->SetWrapS(vtkTextureObject::ClampToEdge);
  psiTex->SetWrapT(vtkTextureObject::ClampToEdge);

  vtkNew<vtkOpenGLFramebufferObject> fbo;
  fbo->SetContext(win);
  win->GetState()->PushFramebufferBindings();
  fbo->PopulateFramebuffer(W, 1, true, 1, VTK_FLOAT, false, 0, 0);

  CheckEmbeddedIntegrators();
  std::printf("%-34s %12s %12s %12s   (over %d segments, %d hard cases)\n", "method", "GLSL-C++",
    "GLSL-ref", "C++-ref", W,
    static_cast<int>(
      std::count_if(cases.begin(), cases.end(), [](const Case& c) { return c.Hard; })));
  for (const psi::IntegrationMethodInfo& info : psi::IntegrationMethodTable())
  {
    if (info.NeedsPreIntegrationTable)
    {
      std::printf("%-34s (needs a pre-integration table: not run by this harness)\n", info.Name);
      continue;
    }
    const char* source = psi::IntegratorGlslSource(info.GlslName);
    if (!source)
    {
      continue; // reported above
    }
    std::string fs = HarnessFS;
    fs.replace(fs.find("//PSI::Integrator::Impl"), 23, source);
    fs.replace(fs.find("//PSI::Integrator::Inputs"), 25, PsiIntegratorInputsFS);
    vtkOpenGLQuadHelper quad(win, nullptr, fs.c_str(), "");
    PSI_CHECK(quad.Program != nullptr, "%s: GLSL does not compile", info.Name);
    if (!quad.Program)
    {
      continue;
    }
    win->GetShaderCache()->ReadyShaderProgram(quad.Program);
    fbo->Bind();
    fbo->ActivateDrawBuffer(0);
    win->GetState()->vtkglViewport(0, 0, W, 1);
    win->GetState()->vtkglDisable(GL_BLEND);
    win->GetState()->vtkglDisable(GL_DEPTH_TEST);
    win->GetState()->vtkglDisable(GL_SCISSOR_TEST);
    tf->Activate();
    tb->Activate();
    tl->Activate();
    psiTex->Activate();
    quad.Program->SetUniformi("frontSamples", tf->GetTextureUnit());
    quad.Program->SetUniformi("backSamples", tb->GetTextureUnit());
    quad.Program->SetUniformi("lengths", tl->GetTextureUnit());
    quad.Program->SetUniformi("psiTable", psiTex->GetTextureUnit());
    const float psiScaleShift[2] = { static_cast<float>((table.N - 1.0) / table.N),
      static_cast<float>(0.5 / table.N) };
    quad.Program->SetUniform2f("psiScaleShift", psiScaleShift);
    quad.Program->SetUniformf("unitDistance", static_cast<float>(UnitDistance));
    quad.Render();
    std::vector<float> out(4 * W);
    fbo->ActivateReadBuffer(0);
    glReadPixels(0, 0, W, 1, GL_RGBA, GL_FLOAT, out.data());
    tf->Deactivate();
    tb->Deactivate();
    tl->Deactivate();
    psiTex->Deactivate();

    CompareWithCpp(info, cases, out, table);
  }
  win->GetState()->PopFramebufferBindings();
  return psitest::Report("TestIntegrationGLSL");
}
