//VTK::System::Dec
//VTK::Output::Dec
// PsiCompositeFS: puts the floating-point volume image (premultiplied) over the scene. Within
// VTK's dual depth peeling (PsiDepthPeelingCalls.h) two draw buffers are bound, blended with
// GL_MAX: the image goes to the first (behind the translucent layers), nothing to the second.
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
  gl_FragData[1] = vec4(0.0);
}
