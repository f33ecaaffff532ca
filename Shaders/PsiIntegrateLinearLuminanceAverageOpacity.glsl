// Linear luminance, average opacity (Moreland 2004, dissertation, §5.3.1, Appendix B.5): tau from
// the averaged opacity of one unit distance; Psi of a homogeneous segment, (1 - zeta) / (tau D).
vec4 integrateSegment(float sf, float sb, float D)
{
  vec4 f = transferFront(sf);
  vec4 b = transferBack(sb);
  // mean opacity through the mean transmittance 1 - alpha (exact in float near alpha = 1)
  float transUnit = 0.5 * (max(1.0 - f.a * unitDistance, 0.0) + max(1.0 - b.a * unitDistance, 0.0));
  // a transmittance of 0 (alpha = 1) is opaque over any length and nothing over none: log(0), and
  // its product with D = 0, are undefined in GLSL (a zero-length segment of an opaque cell)
  float tauD = transUnit > 0.0 ? -log(transUnit) * D / unitDistance : (D > 0.0 ? 1e30 : 0.0);
  float zeta = exp(-tauD);
  // (1 - zeta) / (tau D), by its series where float cancellation would cost ~4e-4 relative
  float psi = tauD < 0.03 ? 1.0 - tauD * (0.5 - tauD * (1.0 / 6.0 - tauD / 24.0)) : (1.0 - zeta) / tauD;
  return vec4(f.rgb * (1.0 - psi) + b.rgb * (psi - zeta), 1.0 - zeta);
}
