#include "PsiShaderComposer.h"

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
#include "PsiRaySegmentsFS.h"
#include "PsiRaySegmentsGS.h"
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
#include "PsiPointIdsGS.h"
#include "PsiPointIdsVS.h"
#include "PsiProjectionClassesGS.h"
#include "PsiSceneDepthFS.h"
#include "PsiSegmentSplitFS.h"
#include "PsiSeparateOpacityFS.h"
#include "PsiSeparateOpacityGS.h"
#include "PsiSeparateOpacityVS.h"
#include "PsiTransferNodesFS.h"
#include "PsiTransferTableFS.h"
#include "PsiVolumeFS.h"
#include "PsiVolumeGS.h"
#include "PsiVolumeVS.h"

#include <cctype>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace psi
{
namespace
{
bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r';
}

std::string Trim(const std::string& s)
{
  size_t b = 0, e = s.size();
  while (b < e && IsSpace(s[b]))
  {
    ++b;
  }
  while (e > b && IsSpace(s[e - 1]))
  {
    --e;
  }
  return s.substr(b, e - b);
}

// A tag: a line holding only //PSI::<Name>::<Name>.
bool IsTag(const std::string& line)
{
  const std::string t = Trim(line);
  if (t.compare(0, 7, "//PSI::") != 0)
  {
    return false;
  }
  const std::string rest = t.substr(7);
  const size_t sep = rest.find("::");
  if (sep == std::string::npos || sep == 0 || sep + 2 >= rest.size())
  {
    return false;
  }
  for (size_t i = 0; i < rest.size(); ++i)
  {
    if (i == sep || i == sep + 1)
    {
      continue;
    }
    if (!std::isalnum(static_cast<unsigned char>(rest[i])))
    {
      return false;
    }
  }
  return true;
}

std::vector<std::string> Lines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
  {
    lines.push_back(line);
  }
  return lines;
}

// The feature of a tag: "//PSI::NearClip::Impl" -> "NearClip".
std::string FeatureOf(const std::string& tag)
{
  return tag.substr(7, tag.find("::", 7) - 7);
}

// The sections of a feature file, in file order: (tag, text). The file's first line is a tag of
// its feature; each tag of that feature starts a section. Tags of other features inside a
// section are kept in its text, to be replaced when their feature is applied.
std::vector<std::pair<std::string, std::string>> Sections(const char* file)
{
  std::vector<std::pair<std::string, std::string>> sections;
  std::string feature;
  for (const std::string& line : Lines(file))
  {
    if (IsTag(line) && (sections.empty() || FeatureOf(Trim(line)) == feature))
    {
      sections.emplace_back(Trim(line), std::string());
      feature = FeatureOf(sections.back().first);
    }
    else if (!sections.empty())
    {
      sections.back().second += line + "\n";
    }
  }
  for (auto& s : sections)
  {
    std::string& t = s.second;
    while (t.size() >= 2 && t[t.size() - 1] == '\n' && t[t.size() - 2] == '\n')
    {
      t.pop_back(); // trailing blank lines separate sections in the file
    }
  }
  return sections;
}

// Replaces the line holding only `tag` in `src` by `with` (which ends with a newline, or is
// empty). False when `src` has no such line.
bool ReplaceTag(std::string& src, const std::string& tag, const std::string& with)
{
  for (size_t pos = src.find(tag); pos != std::string::npos; pos = src.find(tag, pos + 1))
  {
    const size_t nl = pos == 0 ? std::string::npos : src.rfind('\n', pos - 1);
    const size_t begin = nl == std::string::npos ? 0 : nl + 1;
    const size_t eol = src.find('\n', pos);
    const size_t end = eol == std::string::npos ? src.size() : eol + 1;
    const size_t lineEnd = eol == std::string::npos ? src.size() : eol;
    if (Trim(src.substr(begin, lineEnd - begin)) == tag)
    {
      src.replace(begin, end - begin, with);
      return true;
    }
  }
  return false;
}

// Substitutes the sections of feature file `file` into `src`, except those whose tag is listed
// in `skip`.
void Apply(std::string& src, const char* file, const std::set<std::string>& skip = {})
{
  for (const auto& section : Sections(file))
  {
    if (skip.count(section.first))
    {
      continue;
    }
    if (!ReplaceTag(src, section.first, section.second))
    {
      throw std::logic_error("PsiShaderComposer: no tag " + section.first + " to replace");
    }
  }
}

// Replaces every tag left (features that are off) by nothing.
void RemoveTags(std::string& src)
{
  std::string out;
  out.reserve(src.size());
  for (const std::string& line : Lines(src))
  {
    if (!IsTag(line))
    {
      out += line + "\n";
    }
  }
  src.swap(out);
}

std::string Define(const char* name, int value)
{
  return std::string("#define ") + name + " " + std::to_string(value) + "\n";
}

// Components of a GLSL type (the types the geometry shader outputs).
int Components(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "float", 1 }, { "int", 1 }, { "uint", 1 },
    { "vec2", 2 }, { "ivec2", 2 }, { "uvec2", 2 }, { "vec3", 3 }, { "ivec3", 3 }, { "uvec3", 3 },
    { "vec4", 4 }, { "ivec4", 4 }, { "uvec4", 4 }, { "mat2", 4 }, { "mat3", 9 }, { "mat4", 16 } };
  const auto it = sizes.find(type);
  if (it == sizes.end())
  {
    throw std::logic_error("PsiShaderComposer: geometry-shader output of unknown type " + type);
  }
  return it->second;
}

bool Uses(const char* source, const char* name)
{
  return std::string(source).find(name) != std::string::npos;
}

// The segment feature's file: ray segments through the silhouette, or the fan's exact
// perspective segments or screen-linear triple.
const char* SegmentsSource(const ShaderFeatures& f, const char* ray, const char* exact,
  const char* screenLinear)
{
  return f.Silhouette ? ray : f.ExactSegments ? exact : screenLinear;
}

// A separate opacity array is drawn with silhouettes and without adaptive sampling (the mapper
// chooses so); another feature set ignores it.
bool SeparateOpacityOn(const ShaderFeatures& f)
{
  return f.SeparateOpacity && f.Silhouette && !f.Adaptive;
}

// Depth-peeled draws clip the silhouettes' ray segments (the mapper draws silhouettes then).
bool DepthPeelOn(const ShaderFeatures& f)
{
  return f.DepthPeel && f.Silhouette;
}

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
  if (!DepthPeelOn(f))
  {
    skip.insert("//PSI::SeparateOpacity::DepthPeel");
  }
  return skip;
}

std::string ComposeGeometry(const ShaderFeatures& f)
{
  const bool iso = f.IsoCount > 0;
  const bool isoTriangles = iso && f.IsoTriangles;
  std::string gs = PsiVolumeGS;
  std::string counts = Define("PSI_GS_MAX_VERTICES", GeometryOutputVertices(f));
  if (iso)
  {
    counts += Define("PSI_ISO_COUNT", f.IsoCount);
  }
  ReplaceTag(gs, "//PSI::Counts::Dec", counts);
  Apply(gs, PsiProjectionClassesGS);
  if (iso || f.NearClip)
  {
    Apply(gs, PsiPointIdsGS);
  }
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
  if (SeparateOpacityOn(f))
  {
    Apply(gs, PsiSeparateOpacityGS);
  }
  RemoveTags(gs);
  return gs;
}
} // namespace

std::vector<ShaderVariable> DeclaredOutputs(const std::string& src)
{
  std::vector<ShaderVariable> outputs;
  for (const std::string& raw : Lines(src))
  {
    std::istringstream words(raw.substr(0, raw.find("//")));
    std::vector<std::string> w;
    for (std::string word; words >> word;)
    {
      w.push_back(word);
    }
    ShaderVariable v;
    size_t i = 0;
    while (i < w.size() &&
      (w[i] == "flat" || w[i] == "smooth" || w[i] == "noperspective" || w[i] == "centroid"))
    {
      v.Qualifiers += w[i++] + " ";
    }
    if (i + 2 >= w.size() || w[i] != "out")
    {
      continue; // not "out <type> <name>"
    }
    v.Type = w[i + 1];
    v.Name = w[i + 2].substr(0, w[i + 2].find_first_of("[;"));
    const size_t bracket = w[i + 2].find('[');
    v.Count = bracket == std::string::npos ? 1 : std::stoi(w[i + 2].substr(bracket + 1));
    outputs.push_back(v);
  }
  return outputs;
}

bool ShaderFeatures::operator==(const ShaderFeatures& o) const
{
  return Method == o.Method && ExactSegments == o.ExactSegments && Silhouette == o.Silhouette &&
    NearClip == o.NearClip &&
    OpaqueClip == o.OpaqueClip && EarlyDiscard == o.EarlyDiscard && IsoCount == o.IsoCount &&
    IsoSmooth == o.IsoSmooth && IsoTriangles == o.IsoTriangles && Adaptive == o.Adaptive &&
    SeparateOpacity == o.SeparateOpacity && DepthPeel == o.DepthPeel &&
    MaxAdaptiveNodes == o.MaxAdaptiveNodes && MaxLights == o.MaxLights;
}

std::string ShaderFeatures::Defines() const
{
  std::string d;
  if (OpaqueClip)
  {
    d += "#define PSI_OPAQUE_CLIP\n";
  }
  if (Silhouette)
  {
    d += "#define PSI_SILHOUETTE\n";
  }
  else if (ExactSegments)
  {
    d += "#define PSI_EXACT_SEGMENTS\n";
  }
  if (NearClip)
  {
    d += "#define PSI_NEAR_CLIP\n";
  }
  if (IsoCount > 0)
  {
    d += Define("PSI_ISO_COUNT", IsoCount) + Define("PSI_MAX_LIGHTS", MaxLights);
    if (IsoSmooth)
    {
      d += "#define PSI_ISO_SMOOTH\n";
    }
    d += IsoTriangles
      ? "#define PSI_ISO_TRIANGLES\n" + Define("PSI_GS_MAX_VERTICES", GeometryOutputVertices(*this))
      : std::string("#define PSI_ISO_PER_FRAGMENT\n");
  }
  if (EarlyDiscard)
  {
    d += "#define PSI_EARLY_DISCARD\n";
  }
  if (SeparateOpacityOn(*this))
  {
    d += "#define PSI_SEPARATE_OPACITY\n";
  }
  if (DepthPeelOn(*this))
  {
    d += "#define PSI_DEPTH_PEEL\n";
  }
  if (Adaptive)
  {
    d += "#define PSI_ADAPTIVE\n" + Define("PSI_TF_NODES_MAX", MaxAdaptiveNodes);
  }
  return d;
}

std::string ShaderFeatures::Key() const
{
  return this->Defines() + "method " + std::to_string(Method) + "\n";
}

bool SilhouetteChosen(int decomposition)
{
  const char* site = std::getenv("PSI_DECOMPOSITION");
  return decomposition == 2 ? !(site && std::string(site) == "fan") : decomposition == 0;
}

int GeometryOutputVertices(const ShaderFeatures& f)
{
  // PsiProjectionClassesGS.glsl: the fan of class 2, strips of 5 and 3; a silhouette quad
  const int projection = f.Silhouette ? 4 : 8;
  const int surface = 4;    // PsiIsoTrianglesGS.glsl emitSurface: a strip of at most 4
  if (f.IsoCount > 0 && f.IsoTriangles)
  {
    return projection * (f.IsoCount + 1) + surface * f.IsoCount;
  }
  return projection;
}

int ProjectedTrianglesMax(const ShaderFeatures& f)
{
  // class 2: four triangles (Shirley & Tuchman's largest split); a silhouette quad has two
  const int projection = f.Silhouette ? 2 : 4;
  const int surface = 2;    // a marching-tetrahedra quad
  if (f.IsoCount > 0 && f.IsoTriangles)
  {
    return projection * (f.IsoCount + 1) + surface * f.IsoCount;
  }
  return projection;
}

int GeometryOutputComponentsPerVertex(const ShaderFeatures& f)
{
  int total = 4; // gl_Position
  for (const ShaderVariable& v : DeclaredOutputs(ComposeGeometry(f)))
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

ShaderSources ComposeShaders(const ShaderFeatures& f, const char* integratorSource)
{
  const char* integrator = integratorSource ? integratorSource : IntegratorSource(f.Method);
  const bool iso = f.IsoCount > 0;
  const bool isoTriangles = iso && f.IsoTriangles;
  const bool isoPerFragment = iso && !f.IsoTriangles;
  const bool split = isoPerFragment || f.Adaptive;
  ShaderSources out;

  out.Vertex = PsiVolumeVS;
  if (iso || f.NearClip)
  {
    Apply(out.Vertex, PsiPointIdsVS);
  }
  if (SeparateOpacityOn(f))
  {
    Apply(out.Vertex, PsiSeparateOpacityVS);
  }
  RemoveTags(out.Vertex);

  out.Geometry = ComposeGeometry(f);

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
    counts += Define("PSI_MAX_SPLITS",
      (isoPerFragment ? f.IsoCount : 0) + (f.Adaptive ? f.MaxAdaptiveNodes : 0));
  }
  ReplaceTag(fs, "//PSI::Counts::Dec", counts);
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
  if (!ReplaceTag(fs, "//PSI::Integrator::Impl", integratorText))
  {
    throw std::logic_error("PsiShaderComposer: no tag //PSI::Integrator::Impl");
  }
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
  if (DepthPeelOn(f))
  {
    Apply(fs, PsiDepthPeelFS, isoTriangles ? std::set<std::string>{}
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
  if (SeparateOpacityOn(f))
  {
    Apply(fs, PsiSeparateOpacityFS, SeparateOpacitySkips(f, split)); // after the sites' features
  }
  RemoveTags(fs);
  return out;
}

} // namespace psi
