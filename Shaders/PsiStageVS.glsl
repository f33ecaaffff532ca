//PSI::Stage::Main
// The vertex-shader form's entry point (the compute-shader projector calls psiVertexMain from its
// own, PsiProjectCS.glsl).
void main()
{
  psiVertexMain();
}
