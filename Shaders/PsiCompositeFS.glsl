//VTK::System::Dec
//VTK::Output::Dec
// PsiCompositeFS: puts the floating-point volume images (premultiplied) into the framebuffer
// being rendered. Outside depth peeling (peelStage 0) the one image goes over the scene. Within
// VTK's dual depth peeling (PsiDepthPeelingCalls.h; its pass blends with GL_MAX, or "over" in
// its final stage) the images of the stage's intervals go where the pass's GPU ray caster puts
// its rays' colors:
//   stage 1, before the peels: the back image to the back accumulation buffer (draw buffer 0),
//     the front image to the front one (1);
//   stage 2, a peel: the back image to draw buffer 0 (blended into the back accumulation by the
//     pass), and the front image under the front layers composited so far (lastFrontColorTex,
//     premultiplied): rgb = front + (1 - a_front) rgb_image, a = 1 - (1 - a_front)(1 - a_image);
//   stage 3, the final blend: the one image over the back accumulation buffer.
in vec2 texCoord;
uniform sampler2D volumeImage;  // the back interval's image (the only one outside stages 1, 2)
uniform sampler2D frontImage;   // the front interval's image
uniform sampler2D lastFrontColorTex;
uniform int peelStage;
void main()
{
  vec4 back = texture(volumeImage, texCoord);
  vec4 front = peelStage == 1 || peelStage == 2 ? texture(frontImage, texCoord) : vec4(0.0);
  if (back.a <= 0.0 && front.a <= 0.0)
  {
    discard;
  }
  gl_FragData[0] = back;
  gl_FragData[1] = front;
  if (peelStage == 2)
  {
    vec4 layers = texture(lastFrontColorTex, texCoord);
    float t = 1.0 - layers.a;
    gl_FragData[1] = vec4(layers.rgb + t * front.rgb, 1.0 - t * (1.0 - front.a));
  }
}
