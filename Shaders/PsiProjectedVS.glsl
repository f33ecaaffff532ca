//VTK::System::Dec
#extension GL_ARB_shader_bit_encoding : enable
//PSI::Counts::Dec
// PsiProjectedVS: draws the triangles of the compute-shader projector (PsiProjectCS.glsl). Vertex
// v of a pass is PSI_VERTEX_VEC4S texels of `projected` from v * PSI_VERTEX_VEC4S: the clip
// position, then the geometry shader's outputs, which this shader passes on to the fragment
// shader under the same names and interpolation qualifiers.
uniform usamplerBuffer projected; // the bits of each vertex (PsiProjectCS.glsl)

//PSI::Stage::Outputs

void main()
{
  int base = gl_VertexID * PSI_VERTEX_VEC4S;
  gl_Position = uintBitsToFloat(texelFetch(projected, base));
//PSI::Stage::Load
}
