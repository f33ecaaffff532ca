// Average luminance and opacity (Wilhelms and van Gelder; Moreland 2004, dissertation, §6.1,
// Table 6.4): the opacity alpha of one unit distance is averaged, tau = -ln(1 - alpha)
// (Eq. 5.12), color = mean L alpha.
vec4 integrateSegment(float sf, float sb, float D)
{
  vec4 f = transferFront(sf);
  vec4 b = transferBack(sb);
  // mean opacity through the mean transmittance 1 - alpha (exact in float near alpha = 1)
  float transUnit = 0.5 * (max(1.0 - f.a * unitDistance, 0.0) + max(1.0 - b.a * unitDistance, 0.0));
  // a transmittance of 0 (alpha = 1) is opaque over any length and nothing over none: log(0), and
  // its product with D = 0, are undefined in GLSL (a zero-length segment of an opaque cell)
  float tauD = transUnit > 0.0 ? -log(transUnit) * D / unitDistance : (D > 0.0 ? 1e30 : 0.0);
  float alpha = 1.0 - exp(-tauD);
  return vec4(0.5 * (f.rgb + b.rgb) * alpha, alpha);
}
