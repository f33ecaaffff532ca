//VTK::System::Dec
//VTK::Output::Dec
// PsiCompositeFS: puts the floating-point volume image (premultiplied) over the scene.
in vec2 texCoord;
uniform sampler2D volumeImage;
void main()
{
  vec4 c = texture(volumeImage, texCoord);
  if (c.a <= 0.0)
  {
    discard;
  }
  gl_FragData[0] = c;
}
