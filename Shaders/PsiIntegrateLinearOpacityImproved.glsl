// Linear luminance and opacity, improved approximation (Moreland 2004, dissertation, §5.3.2,
// Appendix B.6): zeta from the parabola-corrected mean opacity (Eq. 5.13), Psi from the
// 0.27/0.73-weighted opacity (Eq. 5.14), both of one unit distance.
vec4 integrateSegment(float sf, float sb, float D)
{
  vec4 f = transferFront(sf);
  vec4 b = transferBack(sb);
  // Written in the transmittances tf = 1 - alpha_f, tb = 1 - alpha_b, which are exact in float
  // near alpha = 1: 1 - (mean alpha + 0.108165 d^2) = mean t - 0.108165 d^2, and
  // 1 - (0.27 alpha_b + 0.73 alpha_f) = 0.27 tb + 0.73 tf.
  float tf = max(1.0 - f.a * unitDistance, 0.0), tb = max(1.0 - b.a * unitDistance, 0.0);
  float units = D / unitDistance;
  // pow(0, 0), log(0) and its product with D = 0 are undefined in GLSL: a transmittance of 0
  // (alpha = 1) is opaque over any length and nothing over none
  float zeta = D > 0.0 ? pow(max(0.5 * (tb + tf) - 0.108165 * (tb - tf) * (tb - tf), 0.0), units) : 1.0;
  float t2 = 0.27 * tb + 0.73 * tf;
  float tau2D = t2 > 0.0 ? -log(t2) * units : (D > 0.0 ? 1e30 : 0.0);
  // (1 - e^{-x}) / x by its series where float cancellation would cost ~4e-4 relative
  float psi = tau2D < 0.03 ? 1.0 - tau2D * (0.5 - tau2D * (1.0 / 6.0 - tau2D / 24.0))
                           : (1.0 - exp(-tau2D)) / tau2D;
  return vec4(f.rgb * (1.0 - psi) + b.rgb * (psi - zeta), 1.0 - zeta);
}
