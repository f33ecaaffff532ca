// PsiReferenceIntegrals: the exact segment integrals every integration method is measured
// against, by adaptive Gauss-Kronrod quadrature in long double, independent of Psi and of every
// closed form in Core/. Slow; for tests and benchmarks only (not part of the plugin).
#ifndef PsiReferenceIntegrals_h
#define PsiReferenceIntegrals_h

#include "PsiIntegrationMethods.h"

#include <vector>

namespace psi
{
/// Linear attenuation: the emission-absorption integral with tau and L linear along the segment
/// (Moreland's dissertation §3.1, Eq. 3.8), by nested adaptive quadrature.
Rgba IntegrateReference(const Segment& s);

/// Several media sharing the segment (each `media[k]` with the same D, its own linear tau and L):
/// their attenuations add and so do their emissions, tau = sum tau_k and tau L = sum tau_k L_k
/// (the emission-absorption model of Moreland's dissertation §3.1, Eq. 3.8, with one density per
/// medium), by adaptive quadrature. One medium: IntegrateReference.
Rgba IntegrateReferenceMedia(const std::vector<Segment>& media);

/// Linear opacity: alpha linear, tau(s) = -ln(1 - alpha(s)) / unit (Moreland's dissertation
/// §5.3, Eq. 5.12), luminance linear; adaptive quadrature in long double. Where alpha = 1 over
/// the whole segment (D > 0) the ray takes the front luminance: (Lf, 1) exactly.
Rgba IntegrateReferenceLinearOpacity(const TFSegment& s);

/// The reference of the model `m` approximates.
Rgba IntegrateReferenceFor(Method m, const TFSegment& s);
} // namespace psi

#endif
