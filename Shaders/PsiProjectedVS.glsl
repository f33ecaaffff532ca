//VTK::System::Dec
#extension GL_ARB_shader_bit_encoding : enable
//PSI::Counts::Dec
// PsiProjectedVS: draws the triangles of the compute-shader projector (PsiProjectCS.glsl). Each
// vertex arrives as PSI_VERTEX_VEC4S attributes psiVertex0.. (uvec4, the bits written by the
// compute pass): the clip position, then the geometry shader's outputs, which this shader passes
// on to the fragment shader under the same names and interpolation qualifiers. (Attributes, not
// buffer-texture fetches: a CPU driver's vertex fetch reads them with plain strided loads.)

//PSI::Stage::Outputs

void main()
{
  gl_Position = uintBitsToFloat(psiVertex0);
//PSI::Stage::Load
}
