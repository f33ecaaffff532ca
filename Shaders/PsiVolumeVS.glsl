//VTK::System::Dec
// PsiVolumeVS: one vertex per tetrahedron (Maximo et al. 2010 §3: tetrahedra streamed as
// points). The tetrahedron's four point ids arrive as one attribute; the points (model xyz +
// scalar) are fetched from a texture buffer and moved to view coordinates, where thickness is
// measured. The PointIds tags (PsiPointIdsVS.glsl) pass the ids on when a feature needs them.
//
// psi::ComposeShaders writes this stage in one of two forms (PsiStageInterface.cxx): a vertex
// shader, or the function psiVertexMain of the compute-shader projector (PsiProjectCS.glsl). The
// form's declarations replace //PSI::Stage::Dec: the attribute tetPointIds and tetOut, the
// tetrahedron handed to the geometry code (struct PsiTetrahedron).

//PSI::Stage::Dec
uniform samplerBuffer points; // xyz: model (shifted) coordinates, w: scalar in [0, 1]
uniform mat4 MCVCMatrix;

//PSI::SeparateOpacity::Dec

vec4 viewPoint(uint id)
{
  vec4 p = texelFetch(points, int(id));
  return vec4((MCVCMatrix * vec4(p.xyz, 1.0)).xyz, p.w);
}

void psiVertexMain()
{
  tetOut.points[0] = viewPoint(tetPointIds.x);
  tetOut.points[1] = viewPoint(tetPointIds.y);
  tetOut.points[2] = viewPoint(tetPointIds.z);
  tetOut.points[3] = viewPoint(tetPointIds.w);
//PSI::PointIds::Impl
//PSI::SeparateOpacity::Impl
}
//PSI::Stage::Main
