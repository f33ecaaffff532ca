#include "PsiComputeProjectorComposer.h"

#include "PsiProjectCS.h"
#include "PsiProjectedVS.h"
#include "PsiShaderTags.h"

#include <stdexcept>

namespace psi
{
namespace
{
const char* Swizzle(int size)
{
  static const char* s[] = { "", ".x", ".xy", ".xyz", "" };
  return s[size];
}

// One uvec4 texel from `value` (a float, int or uint scalar or vector of `p.Size`): the bits,
// so that every value (integers, NaN, denormals) passes unchanged.
std::string ToTexel(const TypeShape& p, const std::string& value)
{
  const std::string n = p.Size > 1 ? std::to_string(p.Size) : "";
  const std::string bits = p.Kind == "float" ? "floatBitsToUint(" + value + ")"
    : p.Kind == "int" ? (p.Size > 1 ? "uvec" + n : std::string("uint")) + "(" + value + ")"
                      : value;
  static const char* pad[] = { "", ", 0u, 0u, 0u", ", 0u, 0u", ", 0u", "" };
  return p.Size == 4 ? bits : "uvec4(" + bits + pad[p.Size] + ")";
}

// The value of `p.Size` components back from uvec4 texel expression `texel`.
std::string FromTexel(const TypeShape& p, const std::string& texel)
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
    const TypeShape p = ShapeOf(v.Type); // one texel per column
    declare += Line(OutputDeclaration(v));
    std::string columns;
    for (int c = 0; c < p.Columns; ++c, ++texel)
    {
      const std::string value = p.Columns > 1 ? v.Name + "[" + std::to_string(c) + "]" : v.Name;
      store += Line(
        "  projectedVertices[base + " + std::to_string(texel) + "u] = " + ToTexel(p, value) + ";");
      columns += std::string(c ? ", " : "") + FromTexel(p, "psiVertex" + std::to_string(texel));
    }
    load +=
      Line("  " + v.Name + " = " + (p.Columns > 1 ? v.Type + "(" + columns + ")" : columns) + ";");
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
