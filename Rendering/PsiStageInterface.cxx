#include "PsiStageInterface.h"
#include "PsiShaderFeatures.h"

#include <map>
#include <stdexcept>

namespace psi
{
namespace
{
std::string Declarator(const ShaderVariable& v)
{
  return v.Type + " " + v.Name + (v.Count > 1 ? "[" + std::to_string(v.Count) + "]" : "");
}

std::string WithComment(const std::string& declaration, const ShaderVariable& v)
{
  return declaration + (v.Comment.empty() ? "" : " // " + v.Comment) + "\n";
}

// The members of struct PsiTetrahedron, or of the interface block of the same name (where the
// interpolation qualifiers stay: an integer output of a vertex shader must be flat).
std::string Members(const ShaderFeatures& f, bool qualified)
{
  std::string m;
  for (const ShaderVariable& v : TetrahedronMembers(f))
  {
    m += WithComment("  " + (qualified ? v.Qualifiers : "") + Declarator(v) + ";", v);
  }
  return "PsiTetrahedron\n{\n" + m + "}";
}
} // namespace

TypeShape ShapeOf(const std::string& type)
{
  static const std::map<std::string, TypeShape> shapes = { { "float", { "float", 1, 1 } },
    { "vec2", { "float", 2, 1 } }, { "vec3", { "float", 3, 1 } }, { "vec4", { "float", 4, 1 } },
    { "int", { "int", 1, 1 } }, { "ivec2", { "int", 2, 1 } }, { "ivec3", { "int", 3, 1 } },
    { "ivec4", { "int", 4, 1 } }, { "uint", { "uint", 1, 1 } }, { "uvec2", { "uint", 2, 1 } },
    { "uvec3", { "uint", 3, 1 } }, { "uvec4", { "uint", 4, 1 } }, { "mat2", { "float", 2, 2 } },
    { "mat3", { "float", 3, 3 } }, { "mat4", { "float", 4, 4 } } };
  const auto it = shapes.find(type);
  if (it == shapes.end())
  {
    throw std::logic_error("PsiStageInterface: a stage output of unknown type " + type);
  }
  return it->second;
}

int Components(const std::string& type)
{
  const TypeShape s = ShapeOf(type);
  return s.Size * s.Columns;
}

std::string OutputDeclaration(const ShaderVariable& v)
{
  return v.Qualifiers + "out " + Declarator(v) + ";";
}

std::vector<ShaderVariable> TetrahedronMembers(const ShaderFeatures& f)
{
  std::vector<ShaderVariable> m = { { "", "vec4", "points", 4,
    "view-space xyz, w = scalar in [0, 1] (PsiVolumeVS.glsl)" } };
  if (f.IsoCount > 0 || f.NearClip)
  {
    m.push_back({ "flat ", "uvec4", "ids", 1, "point ids (PsiPointIdsVS.glsl)" });
  }
  if (SeparateOpacityDrawn(f))
  {
    m.push_back({ "", "vec4", "opacity", 1, "opacity scalars (PsiSeparateOpacityVS.glsl)" });
  }
  return m;
}

std::vector<ShaderVariable> GeometryOutputs(const ShaderFeatures& f)
{
  const bool iso = f.IsoCount > 0;
  std::vector<ShaderVariable> out;
  if (SeparateOpacityDrawn(f))
  {
    out.push_back({ "flat ", "vec4", "opacityPlane", 1,
      "o(x) = g_o . x + o0, view coordinates (PsiSeparateOpacityGS.glsl)" });
  }
  if (f.Silhouette) // PsiRaySegmentsGS.glsl
  {
    out.push_back({ "flat ", "vec4", "rayFace0", 1,
      "p0 of each face, its lowest bit 1 where the ray enters (PsiRaySegmentsGS.glsl)" });
    out.push_back({ "flat ", "vec4", "rayFaceX", 1, "px of each face" });
    out.push_back({ "flat ", "vec4", "rayFaceY", 1, "py of each face" });
    out.push_back({ "flat ", "vec4", "scalarRay", 1,
      "a0, b0, c_x, c_y: a = a0 + k u, b = b0 + (1 - k) u, u = x c_x + y c_y, k = 1 parallel" });
    out.push_back({ "smooth ", "vec3", "isoNormal", 1, "marching-tetrahedra surface vertices" });
  }
  else if (f.ExactSegments) // PsiExactSegmentsGS.glsl
  {
    out.push_back({ "smooth ", "vec4", "frontPoint", 1,
      "view-space xyz, w = scalar (PsiExactSegmentsGS.glsl)" });
    out.push_back({ "flat ", "vec4", "backPlane", 1, "n . x = w" });
    out.push_back({ "flat ", "vec4", "scalarGrad", 1,
      "xyz: gradient of the scalar, w: bound on the thickness" });
  }
  else
  {
    out.push_back({ "noperspective ", "vec3", "segment", 1,
      "front scalar, back scalar, thickness (PsiHAPTSegmentsGS.glsl)" });
  }
  if (f.NearClip)
  {
    out.push_back({ "flat ", "ivec4", "clipTet", 1,
      "point ids of a cut cell, x = -1 when not cut (PsiNearClipGS.glsl)" });
  }
  if (iso && !f.IsoTriangles)
  {
    out.push_back({ "flat ", "vec3", "isoG0", 1,
      "normal field g(x) = isoG0 + isoJ (x - isoV0) (PsiIsoPerFragmentGS.glsl)" });
    out.push_back({ "flat ", "mat3", "isoJ", 1, "" });
    out.push_back({ "flat ", "vec3", "isoV0", 1, "" });
  }
  if (iso && f.IsoTriangles)
  {
    out.push_back({ "flat ", "float", "piece", 1,
      "volume piece or surface of the primitive (PsiIsoTrianglesGS.glsl)" });
  }
  return out;
}

std::string VertexStageDeclarations(const ShaderFeatures& f, StageForm form)
{
  if (form == StageForm::Stages)
  {
    return "in uvec4 tetPointIds; // the tetrahedron's point ids, one point per tetrahedron\n"
           "out " +
      Members(f, true) + " tetOut;\n";
  }
  // Initialized, so that compilers that cannot see that main() sets it first do not warn.
  return "uvec4 tetPointIds = uvec4(0u); // set by main() from the visibility order\n"
         "struct " +
    Members(f, false) +
    ";\n"
    "PsiTetrahedron tetOut;\n";
}

std::string GeometryStageDeclarations(const ShaderFeatures& f, StageForm form)
{
  std::string d;
  if (form == StageForm::Stages)
  {
    d = "layout(points) in;\n"
        "layout(triangle_strip, max_vertices = PSI_GS_MAX_VERTICES) out;\n"
        "in " +
      Members(f, true) + " tetIn[];\n";
  }
  else
  {
    d = "PsiTetrahedron tetIn[1]; // tetOut, copied by main()\n";
  }
  for (const ShaderVariable& v : GeometryOutputs(f))
  {
    d += WithComment(form == StageForm::Stages ? OutputDeclaration(v) : Declarator(v) + ";", v);
  }
  return d;
}
} // namespace psi
