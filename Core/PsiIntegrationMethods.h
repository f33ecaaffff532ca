// PsiIntegrationMethods: every ray-integration method of the seeds as a plain function of one
// segment, in double precision (the GLSL versions in Shaders/PsiIntegrate*.glsl follow the same
// formulas in float). Equation numbers refer to Moreland's dissertation (seed 001).
//
// Two optical models are in play:
//  - linear attenuation (methods 1-3, 7): tau linear along the segment, tau = opacity / unit
//    distance (VTK's convention), the model of psi::IntegrateReference;
//  - linear opacity (methods 4-6, seed 001 §5.3): alpha linear along the segment, where alpha is
//    the opacity of one unit distance and tau = -ln(1 - alpha) / unit (Eq. 5.12), the model of
//    psi::IntegrateReferenceLinearOpacity.
// Each method is measured against the reference of the model it approximates.
#ifndef PsiIntegrationMethods_h
#define PsiIntegrationMethods_h

#include "PsiIntegration.h"
#include "PsiVolumeCoreModule.h"

#include <string>
#include <vector>

namespace psi
{

enum class Method
{
  Average = 0,                     ///< 1. average luminance and attenuation (§3.2.2, Eq. 3.16)
  PartialPreIntegration = 1,       ///< 2. Psi table (§5.2)
  LinearExact = 2,                 ///< 3. Williams-Max-Stein closed form (§3.2.3, Eq. 3.28)
  AverageOpacity = 3,              ///< 4. average luminance and opacity (Wilhelms-van Gelder)
  LinearLuminanceAverageOpacity = 4, ///< 5. §5.3.1, Appendix B.5
  LinearOpacityImproved = 5,       ///< 6. §5.3.2, Eqs. 5.13-5.14, Appendix B.6
  FullPreIntegration = 6,          ///< 7. Roettger et al. 3D table per transfer function
  Count = 7
};

PSIVOLUMECORE_EXPORT const char* MethodName(Method m);
/// True for the methods of the linear-opacity model (4-6).
PSIVOLUMECORE_EXPORT bool UsesLinearOpacity(Method m);

/// A segment given by transfer-function values at its ends: luminance and, in `a`, the opacity
/// function's value (in [0, 1]); D in world units; unit = ScalarOpacityUnitDistance.
struct TFSegment
{
  Rgb Lf{ { 0, 0, 0 } }, Lb{ { 0, 0, 0 } };
  double af = 0, ab = 0;
  double D = 0;
  double unit = 1;
};

/// Segment for the linear-attenuation model: tau = a / unit.
PSIVOLUMECORE_EXPORT Segment AttenuationSegment(const TFSegment& s);

/// Psi in closed form (Williams, Max and Stein; seed 001 Eq. 3.28), with erfcx and Dawson's
/// integral evaluated stably (Numerical Recipes' erfc fit, Eq. 3.24, and Rybicki's method), and a
/// series in (tau_b - tau_f) D where the closed form cancels.
PSIVOLUMECORE_EXPORT double PsiClosedForm(double taubD, double taufD);
PSIVOLUMECORE_EXPORT double Erfcx(double x);  ///< e^{x^2} erfc(x), x >= 0
PSIVOLUMECORE_EXPORT double Dawson(double x); ///< e^{-x^2} int_0^x e^{t^2} dt

/// One segment by `m`. For PartialPreIntegration `psiTable` must be given; for
/// FullPreIntegration, `preintegrated` (see PsiPreIntegrationTable.h) is used by the caller
/// instead, so this function evaluates it exactly (the limit of an infinitely fine table).
PSIVOLUMECORE_EXPORT Rgba Integrate(
  Method m, const TFSegment& s, const struct PsiTable* psiTable = nullptr);

} // namespace psi

#endif
