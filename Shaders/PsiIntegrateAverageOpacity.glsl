// Average luminance and opacity (Wilhelms and van Gelder; seed 001 §6.1 Table 6.4): the opacity
// alpha of one unit distance is averaged, tau = -ln(1 - alpha) (Eq. 5.12), color = mean L alpha.
vec4 integrateSegment(float sf, float sb, float D)
{
  vec4 f = transfer(sf);
  vec4 b = transfer(sb);
  float alphaUnit = min(0.5 * (f.a + b.a) * unitDistance, 1.0);
  float tauD = -log(1.0 - alphaUnit) * D / unitDistance;
  float alpha = 1.0 - exp(-tauD);
  return vec4(0.5 * (f.rgb + b.rgb) * alpha, alpha);
}
