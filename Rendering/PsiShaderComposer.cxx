#include "PsiShaderComposer.h"
#include "PsiShaderTags.h"

#include "PsiIntegrationMethods.h"
#include "PsiIntegratorSources.h"

#include "PsiAdaptiveFS.h"
#include "PsiCellGradientGS.h"
#include "PsiDepthPeelFS.h"
#include "PsiEarlyDiscardGS.h"
#include "PsiExactSegmentsFS.h"
#include "PsiExactSegmentsGS.h"
#include "PsiHAPTSegmentsFS.h"
#include "PsiHAPTSegmentsGS.h"
#include "PsiIntegratorInputsFS.h"
#include "PsiIsoFlatNormalsGS.h"
#include "PsiIsoPerFragmentFS.h"
#include "PsiIsoPerFragmentGS.h"
#include "PsiIsoShadeFS.h"
#include "PsiIsoSmoothNormalsGS.h"
#include "PsiIsoTrianglesFS.h"
#include "PsiIsoTrianglesGS.h"
#include "PsiNearClipFS.h"
#include "PsiNearClipGS.h"
#include "PsiOpaqueClipFS.h"
#include "PsiPointIdsVS.h"
#include "PsiProjectionClassesGS.h"
#include "PsiRaySegmentsFS.h"
#include "PsiRaySegmentsGS.h"
#include "PsiSceneDepthFS.h"
#include "PsiSegmentSplitFS.h"
#include "PsiSeparateOpacityFS.h"
#include "PsiSeparateOpacityGS.h"
#include "PsiSeparateOpacityVS.h"
#include "PsiStageGS.h"
#include "PsiStageVS.h"
#include "PsiTransferNodesFS.h"
#include "PsiTransferTableFS.h"
#include "PsiVolumeFS.h"
#include "PsiVolumeGS.h"
#include "PsiVolumeVS.h"

#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace psi
{
namespace
{
std::string Define(const char* name, int value)
{
  return std::string("#define ") + name + " " + std::to_string(value) + "\n";
}

bool Uses(const char* source, const char* name)
{
  return std::string(source).find(name) != std::string::npos;
}

// The segment feature's file: ray segments through the silhouette, or the fan's exact
// perspective segments or screen-linear triple.
const char* SegmentsSource(
  const ShaderFeatures& f, const char* ray, const char* exact, const char* screenLinear)
{
  return f.Silhouette ? ray : f.ExactSegments ? exact : screenLinear;
}

// Depth-peeled draws clip the silhouettes' ray segments (the mapper draws silhouettes then).
// The sections of PsiSeparateOpacityFS.glsl whose sites the other features of `f` leave out.
std::set<std::string> SeparateOpacitySkips(const ShaderFeatures& f, bool split)
{
  std::set<std::string> skip;
  if (!f.OpaqueClip)
  {
    skip.insert("//PSI::SeparateOpacity::OpaqueClip");
  }
  if (!(f.IsoCount > 0 && f.IsoTriangles))
  {
    skip.insert("//PSI::SeparateOpacity::Piece");
  }
  if (!split)
  {
    skip.insert("//PSI::SeparateOpacity::SplitInit");
    skip.insert("//PSI::SeparateOpacity::SplitPiece");
  }
  if (!f.NearClip)
  {
    skip.insert("//PSI::SeparateOpacity::NearClip");
  }
  if (!DepthPeelDrawn(f))
  {
    skip.insert("//PSI::SeparateOpacity::DepthPeel");
  }
  return skip;
}

// The stage form's pieces: in the Stages form the entry points, the geometry shader's emission
// and extension (PsiStage{VS,GS}.glsl); the Functions form has its own in PsiProjectCS.glsl.
void ApplyStageForm(std::string& src, const char* stageFile, StageForm form)
{
  if (form == StageForm::Stages)
  {
    Apply(src, stageFile);
  }
  else
  {
    ReplaceTag(src, "//VTK::System::Dec", ""); // the compute shader has its own #version
  }
}

std::string ComposeVertex(const ShaderFeatures& f, StageForm form)
{
  std::string vs = PsiVolumeVS;
  SubstituteTag(vs, "//PSI::Stage::Dec", VertexStageDeclarations(f, form));
  ApplyStageForm(vs, PsiStageVS, form);
  if (f.IsoCount > 0 || f.NearClip)
  {
    Apply(vs, PsiPointIdsVS);
  }
  if (SeparateOpacityDrawn(f))
  {
    Apply(vs, PsiSeparateOpacityVS);
  }
  RemoveTags(vs);
  return vs;
}

std::string ComposeGeometry(const ShaderFeatures& f, StageForm form)
{
  const bool iso = f.IsoCount > 0;
  const bool isoTriangles = iso && f.IsoTriangles;
  std::string gs = PsiVolumeGS;
  std::string counts = Define("PSI_GS_MAX_VERTICES", GeometryOutputVertices(f));
  if (iso)
  {
    counts += Define("PSI_ISO_COUNT", f.IsoCount);
  }
  SubstituteTag(gs, "//PSI::Counts::Dec", counts);
  SubstituteTag(gs, "//PSI::Stage::Dec", GeometryStageDeclarations(f, form));
  ApplyStageForm(gs, PsiStageGS, form);
  Apply(gs, PsiProjectionClassesGS);
  if (f.Silhouette || f.ExactSegments || iso)
  {
    Apply(gs, PsiCellGradientGS);
  }
  Apply(gs, SegmentsSource(f, PsiRaySegmentsGS, PsiExactSegmentsGS, PsiHAPTSegmentsGS));
  if (f.NearClip)
  {
    Apply(gs, PsiNearClipGS);
  }
  if (iso)
  {
    Apply(gs, f.IsoSmooth ? PsiIsoSmoothNormalsGS : PsiIsoFlatNormalsGS);
    Apply(gs, isoTriangles ? PsiIsoTrianglesGS : PsiIsoPerFragmentGS);
  }
  if (f.EarlyDiscard)
  {
    // Marching tetrahedra test each volume piece; otherwise the whole cell is tested.
    Apply(gs, PsiEarlyDiscardGS,
      { isoTriangles ? "//PSI::EarlyDiscard::Cell" : "//PSI::EarlyDiscard::Piece" });
  }
  if (SeparateOpacityDrawn(f))
  {
    Apply(gs, PsiSeparateOpacityGS);
  }
  RemoveTags(gs);
  return gs;
}
} // namespace

int GeometryOutputComponentsPerVertex(const ShaderFeatures& f)
{
  int total = 4; // gl_Position
  for (const ShaderVariable& v : GeometryOutputs(f))
  {
    total += v.Count * Components(v.Type);
  }
  return total;
}

bool FitsGeometryOutputLimits(const ShaderFeatures& f, int maxVertices, int maxTotalComponents)
{
  const long long vertices = GeometryOutputVertices(f);
  return vertices <= maxVertices &&
    vertices * GeometryOutputComponentsPerVertex(f) <= maxTotalComponents;
}

const char* IntegratorSource(int method)
{
  const IntegrationMethodInfo* info = FindIntegrationMethod(method);
  return IntegratorGlslSource(
    (info ? *info : GetIntegrationMethodInfo(Method::PartialPreIntegration)).GlslName);
}

ShaderSources ComposeShaders(const ShaderFeatures& f, const char* integratorSource, StageForm form)
{
  const char* integrator = integratorSource ? integratorSource : IntegratorSource(f.Method);
  const bool iso = f.IsoCount > 0;
  const bool isoTriangles = iso && f.IsoTriangles;
  const bool isoPerFragment = iso && !f.IsoTriangles;
  const bool split = isoPerFragment || f.Adaptive;
  ShaderSources out;

  out.Vertex = ComposeVertex(f, form);
  out.Geometry = ComposeGeometry(f, form);

  std::string& fs = out.Fragment;
  fs = PsiVolumeFS;
  std::string counts;
  if (iso)
  {
    counts += Define("PSI_ISO_COUNT", f.IsoCount) + Define("PSI_MAX_LIGHTS", f.MaxLights);
  }
  if (f.Adaptive)
  {
    counts += Define("PSI_TF_NODES_MAX", f.MaxAdaptiveNodes);
  }
  if (split)
  {
    counts += Define(
      "PSI_MAX_SPLITS", (isoPerFragment ? f.IsoCount : 0) + (f.Adaptive ? f.MaxAdaptiveNodes : 0));
  }
  SubstituteTag(fs, "//PSI::Counts::Dec", counts);
  std::set<std::string> unusedInputs;
  if (!Uses(integrator, "psiCoord") && !Uses(integrator, "psiTable"))
  {
    unusedInputs.insert("//PSI::Integrator::PsiTable");
  }
  if (!Uses(integrator, "unitDistance"))
  {
    unusedInputs.insert("//PSI::Integrator::UnitDistance");
  }
  if (!Uses(integrator, "preIntegrated") && !Uses(integrator, "preScalarScaleShift"))
  {
    unusedInputs.insert("//PSI::Integrator::PreIntegrated");
  }
  Apply(fs, PsiIntegratorInputsFS, unusedInputs);
  std::string integratorText = integrator;
  if (!integratorText.empty() && integratorText.back() != '\n')
  {
    integratorText += '\n';
  }
  SubstituteTag(fs, "//PSI::Integrator::Impl", integratorText);
  Apply(fs, f.Adaptive ? PsiTransferNodesFS : PsiTransferTableFS);
  Apply(fs, SegmentsSource(f, PsiRaySegmentsFS, PsiExactSegmentsFS, PsiHAPTSegmentsFS));
  if (f.NearClip)
  {
    Apply(fs, PsiNearClipFS);
  }
  if (f.NearClip || f.OpaqueClip)
  {
    Apply(fs, PsiSceneDepthFS);
  }
  if (f.OpaqueClip)
  {
    Apply(fs, PsiOpaqueClipFS);
  }
  if (iso)
  {
    Apply(fs, PsiIsoShadeFS);
  }
  if (isoTriangles)
  {
    Apply(fs, PsiIsoTrianglesFS);
  }
  if (DepthPeelDrawn(f))
  {
    Apply(fs, PsiDepthPeelFS,
      isoTriangles ? std::set<std::string>{}
                   : std::set<std::string>{ "//PSI::DepthPeel::Surface" });
  }
  if (split)
  {
    Apply(fs, PsiSegmentSplitFS); // before its features, whose tags it holds
  }
  if (isoPerFragment)
  {
    Apply(fs, PsiIsoPerFragmentFS);
  }
  if (f.Adaptive)
  {
    Apply(fs, PsiAdaptiveFS);
  }
  if (SeparateOpacityDrawn(f))
  {
    Apply(fs, PsiSeparateOpacityFS, SeparateOpacitySkips(f, split)); // after the sites' features
  }
  RemoveTags(fs);
  if (f.RasterFloor) // the shaded main kept but never called: the compiler drops its work
  {
    const std::string shaded = "void main()\n{";
    fs.replace(fs.find(shaded), shaded.size(), "void shadedMain()\n{");
    fs += "\nvoid main()\n{\n  gl_FragData[0] = vec4(0.02);\n}\n";
  }
  return out;
}

} // namespace psi
