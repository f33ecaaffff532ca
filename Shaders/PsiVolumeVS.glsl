//VTK::System::Dec
// PsiVolumeVS: one vertex per tetrahedron (Maximo et al. 2010 §3: tetrahedra streamed as
// points). The tetrahedron's four point ids arrive as one attribute; the points (model xyz +
// scalar) are fetched from a texture buffer and moved to view coordinates, where thickness is
// measured. The PointIds tags (PsiPointIdsVS.glsl) pass the ids on when a feature needs them.

in uvec4 tetPointIds;
uniform samplerBuffer points; // xyz: model (shifted) coordinates, w: scalar in [0, 1]
uniform mat4 MCVCMatrix;

out vec4 vsP0; // view-space xyz, w = scalar
out vec4 vsP1;
out vec4 vsP2;
out vec4 vsP3;
//PSI::PointIds::Dec
//PSI::SeparateOpacity::Dec

vec4 viewPoint(uint id)
{
  vec4 p = texelFetch(points, int(id));
  return vec4((MCVCMatrix * vec4(p.xyz, 1.0)).xyz, p.w);
}

void main()
{
  vsP0 = viewPoint(tetPointIds.x);
  vsP1 = viewPoint(tetPointIds.y);
  vsP2 = viewPoint(tetPointIds.z);
  vsP3 = viewPoint(tetPointIds.w);
//PSI::PointIds::Impl
//PSI::SeparateOpacity::Impl
}
