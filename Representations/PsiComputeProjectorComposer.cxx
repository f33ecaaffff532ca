#include "PsiComputeProjectorComposer.h"

#include "PsiProjectCS.h"
#include "PsiProjectedVS.h"
#include "PsiShaderTags.h"

#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace psi
{
namespace
{
// How one stage output travels through vec4 texels: `Columns` texels, each holding `Size`
// components of kind float, int or uint (the integer kinds as float bits).
struct Packing
{
  std::string Kind; // "float", "int", "uint"
  int Size = 1;
  int Columns = 1;
};

Packing PackingOf(const std::string& type)
{
  static const std::regex vector("(|i|u)vec([234])"), matrix("mat([234])");
  std::smatch m;
  Packing p;
  if (type == "float" || type == "int" || type == "uint")
  {
    p.Kind = type;
  }
  else if (std::regex_match(type, m, vector))
  {
    p.Kind = m[1] == "i" ? "int" : m[1] == "u" ? "uint" : "float";
    p.Size = std::stoi(m[2]);
  }
  else if (std::regex_match(type, m, matrix))
  {
    p.Kind = "float";
    p.Size = p.Columns = std::stoi(m[1]);
  }
  else
  {
    throw std::logic_error("PsiComputeProjectorComposer: cannot pass on an output of type " + type);
  }
  return p;
}

const char* Swizzle(int size)
{
  static const char* s[] = { "", ".x", ".xy", ".xyz", "" };
  return s[size];
}

// One uvec4 texel from `value` (a float, int or uint scalar or vector of `p.Size`): the bits,
// so that every value (integers, NaN, denormals) passes unchanged.
std::string ToTexel(const Packing& p, const std::string& value)
{
  const std::string n = p.Size > 1 ? std::to_string(p.Size) : "";
  const std::string bits = p.Kind == "float" ? "floatBitsToUint(" + value + ")"
    : p.Kind == "int" ? (p.Size > 1 ? "uvec" + n : std::string("uint")) + "(" + value + ")"
                      : value;
  static const char* pad[] = { "", ", 0u, 0u, 0u", ", 0u, 0u", ", 0u", "" };
  return p.Size == 4 ? bits : "uvec4(" + bits + pad[p.Size] + ")";
}

// The value of `p.Size` components back from uvec4 texel expression `texel`.
std::string FromTexel(const Packing& p, const std::string& texel)
{
  const std::string v = texel + Swizzle(p.Size);
  const std::string n = p.Size > 1 ? std::to_string(p.Size) : "";
  return p.Kind == "float" ? "uintBitsToFloat(" + v + ")"
    : p.Kind == "int"      ? (p.Size > 1 ? "ivec" + n : std::string("int")) + "(" + v + ")"
                           : v;
}

std::string Line(const std::string& s)
{
  return s + "\n";
}

std::string ReplaceAll(std::string s, const std::regex& re, const std::string& with)
{
  return std::regex_replace(s, re, with);
}

// The composed vertex shader as the function psiVertexMain: its attribute and its outputs are
// globals (the geometry code reads the outputs as one-element arrays).
std::string VertexStage(std::string vs, std::set<std::string>& uniforms)
{
  std::string out;
  std::istringstream lines(vs);
  std::vector<std::string> outputs;
  for (const ShaderVariable& v : DeclaredOutputs(vs))
  {
    outputs.push_back(v.Name);
  }
  for (std::string line; std::getline(lines, line);)
  {
    static const std::regex outDecl("^\\s*((flat|smooth|noperspective)\\s+)?out\\s+(\\w+)\\s+(\\w+)\\s*;(.*)");
    static const std::regex inDecl("^\\s*in\\s+(\\w+)\\s+(\\w+)\\s*;.*");
    if (line.find("//VTK::System::Dec") != std::string::npos)
    {
      continue;
    }
    line = std::regex_replace(line, outDecl, "$3 $4[1];$5"); // the geometry stage's input
    if (line.compare(0, 8, "uniform ") == 0)
    {
      uniforms.insert(line);
    }
    // The vertex attribute becomes a global that main() sets; initialized, so that compilers
    // that cannot see main() set it first do not warn of a read before a write.
    out += Line(std::regex_replace(line, inDecl, "$1 $2 = $1(0);"));
  }
  for (const std::string& name : outputs)
  {
    out = ReplaceAll(out, std::regex("\\b" + name + "\\b(?!\\[)"), name + "[0]");
  }
  return ReplaceAll(out, std::regex("\\bvoid main\\(\\)"), "void psiVertexMain()");
}

// The composed geometry shader as the function psiGeometryMain: inputs are one-element arrays,
// outputs globals, and the emission goes to the projector's buffers.
std::string GeometryStage(const std::string& gs, const std::set<std::string>& vertexUniforms)
{
  std::string out;
  std::istringstream lines(gs);
  static const std::regex layout("^\\s*layout\\(.*\\)\\s*(in|out)\\s*;.*");
  static const std::regex inDecl("^\\s*(flat\\s+)?in\\s+(\\w+)\\s+(\\w+)\\[\\]\\s*;(.*)");
  static const std::regex outDecl(
    "^\\s*((flat|smooth|noperspective|centroid)\\s+)*out\\s+(\\w+)\\s+(\\w+)\\s*;(.*)");
  for (std::string line; std::getline(lines, line);)
  {
    if (line.find("//VTK::System::Dec") != std::string::npos || line.rfind("#extension", 0) == 0 ||
      std::regex_match(line, layout) || vertexUniforms.count(line))
    {
      continue;
    }
    if (std::regex_match(line, inDecl))
    {
      continue; // declared by the vertex stage, as its outputs
    }
    out += Line(std::regex_replace(line, outDecl, "$3 $4;$5"));
  }
  out = ReplaceAll(out, std::regex("\\bEmitVertex\\(\\)"), "psiEmitVertex()");
  out = ReplaceAll(out, std::regex("\\bEndPrimitive\\(\\)"), "psiEndPrimitive()");
  out = ReplaceAll(out, std::regex("\\bgl_Position\\b"), "psiPosition");
  // The emission functions are defined after the geometry code: declare them first.
  return "void psiEmitVertex();\nvoid psiEndPrimitive();\n" +
    ReplaceAll(out, std::regex("\\bvoid main\\(\\)"), "void psiGeometryMain()");
}
} // namespace

ComputeProjectorSources ComposeComputeProjector(
  const ShaderFeatures& f, const char* integratorSource)
{
  const ShaderSources stages = ComposeShaders(f, integratorSource);
  ComputeProjectorSources out;
  out.SlotVertices = GeometryOutputVertices(f);
  out.SlotTriangles = ProjectedTrianglesMax(f);
  std::string store, declare, load;
  int texel = 1; // texel 0: the clip position
  for (const ShaderVariable& v : DeclaredOutputs(stages.Geometry))
  {
    if (v.Count != 1)
    {
      throw std::logic_error("PsiComputeProjectorComposer: cannot pass on the array " + v.Name);
    }
    const Packing p = PackingOf(v.Type);
    declare += Line(v.Qualifiers + "out " + v.Type + " " + v.Name + ";");
    std::string columns;
    for (int c = 0; c < p.Columns; ++c, ++texel)
    {
      const std::string value = p.Columns > 1 ? v.Name + "[" + std::to_string(c) + "]" : v.Name;
      store += Line("  projectedVertices[base + " + std::to_string(texel) + "u] = " +
        ToTexel(p, value) + ";");
      columns += std::string(c ? ", " : "") + FromTexel(p, "psiVertex" + std::to_string(texel));
    }
    load += Line("  " + v.Name + " = " + (p.Columns > 1 ? v.Type + "(" + columns + ")" : columns) +
      ";");
  }
  out.Vec4sPerVertex = texel;
  for (int t = 0; t < texel; ++t)
  {
    declare += Line("in uvec4 psiVertex" + std::to_string(t) + ";");
  }
  const std::string counts = "#define PSI_SLOT_VERTICES " + std::to_string(out.SlotVertices) +
    "\n#define PSI_SLOT_TRIANGLES " + std::to_string(out.SlotTriangles) +
    "\n#define PSI_VERTEX_VEC4S " + std::to_string(out.Vec4sPerVertex) + "\n";

  std::set<std::string> vertexUniforms;
  out.Compute = PsiProjectCS;
  SubstituteTag(out.Compute, "//PSI::Counts::Dec", "#version 430 core\n" + counts);
  SubstituteTag(out.Compute, "//PSI::Stage::Vertex", VertexStage(stages.Vertex, vertexUniforms));
  SubstituteTag(out.Compute, "//PSI::Stage::Geometry", GeometryStage(stages.Geometry, vertexUniforms));
  SubstituteTag(out.Compute, "//PSI::Stage::Store", store);

  out.Vertex = PsiProjectedVS;
  SubstituteTag(out.Vertex, "//PSI::Counts::Dec", counts);
  SubstituteTag(out.Vertex, "//PSI::Stage::Outputs", declare);
  SubstituteTag(out.Vertex, "//PSI::Stage::Load", load);
  out.Fragment = stages.Fragment;
  return out;
}

} // namespace psi
