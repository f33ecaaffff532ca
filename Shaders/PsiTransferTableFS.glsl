//PSI::Transfer::Impl
// The transfer function as its sampled table (psi::SampleTransferFunction), linearly filtered.
uniform sampler1D transferFunction; // N samples, rgb = luminance, a = attenuation (1/length)
uniform vec2 tfScaleShift;          // texcoord = s * scale + shift (texel centers)

vec4 transfer(float s)
{
  return texture(transferFunction, s * tfScaleShift.x + tfScaleShift.y);
}
