//PSI::Stage::Extensions
#extension GL_ARB_shader_bit_encoding : enable
//PSI::Stage::Emit
// The geometry-shader form's end of a vertex and of a strip (the compute-shader projector writes
// its vertices into buffers instead, PsiProjectCS.glsl).
void psiEmitVertex(vec4 position)
{
  gl_Position = position;
  EmitVertex();
}

void psiEndPrimitive()
{
  EndPrimitive();
}

//PSI::Stage::Main
// The geometry-shader form's entry point (the compute-shader projector calls psiGeometryMain from
// its own, PsiProjectCS.glsl).
void main()
{
  psiGeometryMain();
}
