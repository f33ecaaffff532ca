// Linear luminance, average opacity (seed 001 §5.3.1, Appendix B.5): tau from the averaged
// opacity of one unit distance; Psi of a homogeneous segment, (1 - zeta) / (tau D).
vec4 integrateSegment(float sf, float sb, float D)
{
  vec4 f = transfer(sf);
  vec4 b = transfer(sb);
  float alphaUnit = min(0.5 * (f.a + b.a) * unitDistance, 1.0);
  float tauD = -log(1.0 - alphaUnit) * D / unitDistance;
  float zeta = exp(-tauD);
  float psi = tauD < 1e-4 ? 1.0 - 0.5 * tauD : (1.0 - zeta) / tauD;
  return vec4(f.rgb * (1.0 - psi) + b.rgb * (psi - zeta), 1.0 - zeta);
}
