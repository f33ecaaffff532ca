// Partial pre-integration (Moreland & Angel 2004 §4, Eqs. 7, 8, 11, 12):
//   zeta = exp(-(tau_b + tau_f) D / 2),  Psi = table(gamma_b, gamma_f) (warped, PsiPartialPreIntegrationTable.h),
//   color = Lb (Psi - zeta) + Lf (1 - Psi),  alpha = 1 - zeta.
vec4 integrateSegment(float sf, float sb, float D)
{
  vec4 f = transferFront(sf);
  vec4 b = transferBack(sb);
  vec2 tauD = vec2(b.a, f.a) * D;
  float psi = texture(psiTable, psiCoord(tauD)).r;
  float zeta = exp(-0.5 * (tauD.x + tauD.y));
  return vec4(b.rgb * (psi - zeta) + f.rgb * (1.0 - psi), 1.0 - zeta);
}
