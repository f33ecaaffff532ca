//PSI::Integrator::PsiTable
// Partial pre-integration (Moreland & Angel 2004 Eqs. 7, 8, 11, 12): the Psi table.
uniform sampler2D psiTable;         // Psi(gamma_b, gamma_f), Moreland & Angel 2004 Eq. 12
uniform vec2 psiScaleShift;         // texcoord = u * scale + shift (texel centers)

// Psi table coordinate of (tau_b D, tau_f D): gamma = tau D / (tau D + 1) (Moreland & Angel 2004
// Eq. 11), warped to u = 1 - sqrt(1 - gamma) = 1 - 1/sqrt(tau D + 1) so that the sqrt(1 - gamma)
// edge behavior of Psi is linear in the table (PsiPartialPreIntegrationTable.h). tau D = inf gives u = 1, not NaN.
vec2 psiCoord(vec2 tauD)
{
  return (1.0 - inversesqrt(tauD + 1.0)) * psiScaleShift.x + psiScaleShift.y;
}

//PSI::Integrator::UnitDistance
// The linear-opacity methods (Moreland 2004, dissertation, §5.3): opacity of one unit distance.
uniform float unitDistance;         // ScalarOpacityUnitDistance

//PSI::Integrator::PreIntegrated
// Full pre-integration (Röttger et al. 2000): the 3D table over (front scalar, back scalar,
// length) for the current transfer function. Its length axis is logarithmic (Kraus, Qiao & Ebert
// 2004; psi::PreIntegrationLengthAxis): (1 / l_min, (n - 2) / ln(l_max / l_min), n - 1, 1 / n).
uniform sampler3D preIntegrated;
uniform vec2 preScalarScaleShift;
uniform vec4 preLengthAxis;
