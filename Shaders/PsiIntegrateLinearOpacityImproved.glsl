// Linear luminance and opacity, improved approximation (seed 001 §5.3.2, Appendix B.6): zeta from
// the parabola-corrected mean opacity (Eq. 5.13), Psi from the 0.27/0.73-weighted opacity
// (Eq. 5.14), both of one unit distance.
vec4 integrateSegment(float sf, float sb, float D)
{
  vec4 f = transfer(sf);
  vec4 b = transfer(sb);
  float af = min(f.a * unitDistance, 1.0), ab = min(b.a * unitDistance, 1.0);
  float units = D / unitDistance;
  float zeta = pow(max(1.0 - (0.5 * (ab + af) + 0.108165 * (ab - af) * (ab - af)), 0.0), units);
  float tau2D = -log(1.0 - min(0.27 * ab + 0.73 * af, 1.0)) * units;
  float psi = tau2D < 1e-4 ? 1.0 - 0.5 * tau2D : (1.0 - exp(-tau2D)) / tau2D;
  return vec4(f.rgb * (1.0 - psi) + b.rgb * (psi - zeta), 1.0 - zeta);
}
