//VTK::System::Dec
//VTK::Output::Dec
// PsiOpaqueMaskFS: early ray termination for front-to-back compositing. Between chunks of the
// visibility order, this full-screen pass writes the nearest depth (0) where the volume image
// composited so far is opaque (alpha >= saturatedOpacity, psi::SaturatedOpacity), and nothing
// elsewhere; the volume's fragments there then fail the depth test (GL_LESS) before they are
// shaded. Its colour writes are masked: it only reads the image (after a texture barrier).
in vec2 texCoord;
uniform sampler2D volumeImage; // premultiplied, composited "under" so far
uniform float saturatedOpacity;
void main()
{
  if (texture(volumeImage, texCoord).a < saturatedOpacity)
  {
    discard;
  }
  gl_FragDepth = 0.0;
}
