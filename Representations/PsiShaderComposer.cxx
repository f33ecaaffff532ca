#include "PsiShaderComposer.h"
#include "PsiVolumeFS.h"
#include "PsiVolumeGS.h"
#include "PsiVolumeVS.h"
namespace psi
{
namespace
{
void Substitute(std::string& src, const std::string& tag, const std::string& with)
{
  const auto pos = src.find(tag);
  if (pos != std::string::npos)
  {
    src.replace(pos, tag.size(), with);
  }
}
int Vertices(const ShaderFeatures& f)
{
  return 8 * (f.IsoCount + 1) + 4 * f.IsoCount;
}
std::string Defines(const ShaderFeatures& f)
{
  std::string d;
  if (f.OpaqueClip) d += "#define PSI_OPAQUE_CLIP\n";
  if (f.ExactSegments) d += "#define PSI_EXACT_SEGMENTS\n";
  if (f.NearClip) d += "#define PSI_NEAR_CLIP\n";
  if (f.IsoCount > 0)
  {
    d += "#define PSI_ISO_COUNT " + std::to_string(f.IsoCount) + "\n";
    d += "#define PSI_MAX_LIGHTS " + std::to_string(f.MaxLights) + "\n";
    if (f.IsoSmooth) d += "#define PSI_ISO_SMOOTH\n";
    if (f.IsoTriangles)
      d += "#define PSI_ISO_TRIANGLES\n#define PSI_GS_MAX_VERTICES " + std::to_string(Vertices(f)) + "\n";
    else
      d += "#define PSI_ISO_PER_FRAGMENT\n";
  }
  if (f.EarlyDiscard) d += "#define PSI_EARLY_DISCARD\n";
  if (f.Adaptive) d += "#define PSI_ADAPTIVE\n#define PSI_TF_NODES_MAX " + std::to_string(f.MaxAdaptiveNodes) + "\n";
  return d;
}
}
std::string ShaderFeatures::Key() const
{
  return Defines(*this) + std::to_string(this->Method);
}
bool FitsGeometryOutputLimits(const ShaderFeatures& f, int maxVertices, int maxComponents)
{
  const int comps = 4 + (f.ExactSegments ? 12 : 3) + 1 + (f.NearClip ? 4 : 0);
  return Vertices(f) <= maxVertices && comps * Vertices(f) <= maxComponents;
}
ShaderSources ComposeShaders(const ShaderFeatures& f, const char* integrator)
{
  ShaderSources s{ PsiVolumeVS, PsiVolumeGS, PsiVolumeFS };
  const std::string d = Defines(f);
  Substitute(s.Vertex, "//PSI::Features::Dec", d);
  Substitute(s.Geometry, "//PSI::Features::Dec", d);
  Substitute(s.Fragment, "//PSI::Features::Dec", d);
  Substitute(s.Fragment, "//PSI::Integrator::Impl", integrator);
  return s;
}
}
