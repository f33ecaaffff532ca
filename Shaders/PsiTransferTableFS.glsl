//PSI::Transfer::Impl
// The transfer function as its sampled table (psi::SampleTransferFunction), linearly filtered.
uniform sampler2D transferFunction; // N x 1, rgb = luminance, a = attenuation (1/length)
uniform vec2 tfScaleShift;          // texcoord = s * scale + shift (texel centers)

vec4 transfer(float s)
{
  return texture(transferFunction, vec2(s * tfScaleShift.x + tfScaleShift.y, 0.5));
}
