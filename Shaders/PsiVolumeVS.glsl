//VTK::System::Dec
//PSI::Features::Dec
// PsiVolumeVS: one vertex per tetrahedron (HAPT, seed 002 §3: tetrahedra streamed as points).
// The tetrahedron's four point ids arrive as one attribute; the points (model xyz + scalar) are
// fetched from a texture buffer and moved to view coordinates, where thickness is measured.

in uvec4 tetPointIds;
uniform samplerBuffer points; // xyz: model coordinates (shifted), w: scalar
uniform mat4 MCVCMatrix;

out vec4 vsP0; // view-space xyz, w = scalar
out vec4 vsP1;
out vec4 vsP2;
out vec4 vsP3;
#if defined(PSI_ISO_COUNT) || defined(PSI_NEAR_CLIP)
// Isosurface and near-plane variants: the point ids go on to the geometry shader (smoothed point
// gradients as isosurface normals; the fragment shader's exact clipping of a cut cell).
flat out uvec4 vsIds;
#endif

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
#if defined(PSI_ISO_COUNT) || defined(PSI_NEAR_CLIP)
  vsIds = tetPointIds;
#endif
}
