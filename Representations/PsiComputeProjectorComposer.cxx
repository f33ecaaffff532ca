#include "PsiComputeProjectorComposer.h"

#include "PsiProjectCS.h"
#include "PsiProjectedVS.h"
#include "PsiShaderTags.h"

#include <map>
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
  static const std::map<std::string, Packing> packings = { { "float", { "float", 1, 1 } },
    { "vec2", { "float", 2, 1 } }, { "vec3", { "float", 3, 1 } }, { "vec4", { "float", 4, 1 } },
    { "int", { "int", 1, 1 } }, { "ivec2", { "int", 2, 1 } }, { "ivec3", { "int", 3, 1 } },
    { "ivec4", { "int", 4, 1 } }, { "uint", { "uint", 1, 1 } }, { "uvec2", { "uint", 2, 1 } },
    { "uvec3", { "uint", 3, 1 } }, { "uvec4", { "uint", 4, 1 } }, { "mat2", { "float", 2, 2 } },
    { "mat3", { "float", 3, 3 } }, { "mat4", { "float", 4, 4 } } };
  const auto it = packings.find(type);
  if (it == packings.end())
  {
    throw std::logic_error("PsiComputeProjectorComposer: cannot pass on an output of type " + type);
  }
  return it->second;
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

} // namespace

ComputeProjectorSources ComposeComputeProjector(
  const ShaderFeatures& f, const char* integratorSource)
{
  const ShaderSources stages = ComposeShaders(f, integratorSource, StageForm::Functions);
  ComputeProjectorSources out;
  out.SlotVertices = GeometryOutputVertices(f);
  out.SlotTriangles = ProjectedTrianglesMax(f);
  std::string store, declare, load;
  int texel = 1; // texel 0: the clip position
  for (const ShaderVariable& v : GeometryOutputs(f))
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

  out.Compute = PsiProjectCS;
  SubstituteTag(out.Compute, "//PSI::Counts::Dec", "#version 430 core\n" + counts);
  SubstituteTag(out.Compute, "//PSI::Stage::Vertex", stages.Vertex);
  SubstituteTag(out.Compute, "//PSI::Stage::Geometry", stages.Geometry);
  SubstituteTag(out.Compute, "//PSI::Stage::Store", store);

  out.Vertex = PsiProjectedVS;
  SubstituteTag(out.Vertex, "//PSI::Counts::Dec", counts);
  SubstituteTag(out.Vertex, "//PSI::Stage::Outputs", declare);
  SubstituteTag(out.Vertex, "//PSI::Stage::Load", load);
  out.Fragment = stages.Fragment;
  return out;
}

} // namespace psi
