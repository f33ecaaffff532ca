//PSI::Transfer::Impl
// The transfer function as its sampled table (psi::SampleTransferFunction), linearly filtered.
uniform sampler1D transferFunction; // N samples, rgb = luminance, a = attenuation (1/length)
uniform vec2 tfScaleShift;          // texcoord = s * scale + shift (texel centers); s in [0, 1]

vec4 transfer(float s)
{
  return texture(transferFunction, s * tfScaleShift.x + tfScaleShift.y);
}

// The transfer function at the segment's front and back ends (the integrators' inputs); with a
// separate opacity array the attenuation comes from the opacity scalar there
// (PsiSeparateOpacityFS.glsl).
vec4 transferFront(float s)
{
  vec4 v = transfer(s);
//PSI::SeparateOpacity::Front
  return v;
}

vec4 transferBack(float s)
{
  vec4 v = transfer(s);
//PSI::SeparateOpacity::Back
  return v;
}
