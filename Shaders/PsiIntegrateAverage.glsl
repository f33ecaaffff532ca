// Shirley-Tuchman average luminance and attenuation (Moreland 2004, dissertation, §3.2;
// Moreland & Angel 2004 §4):
// L = (Lf + Lb)/2, tau = (tau_f + tau_b)/2, alpha = 1 - exp(-tau D), color = L alpha.
vec4 integrateSegment(float sf, float sb, float D)
{
  vec4 f = transferFront(sf);
  vec4 b = transferBack(sb);
  float tau = 0.5 * (f.a + b.a);
  float alpha = 1.0 - exp(-tau * D);
  return vec4(0.5 * (f.rgb + b.rgb) * alpha, alpha);
}
