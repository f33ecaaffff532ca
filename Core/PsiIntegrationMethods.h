// PsiIntegrationMethods: every ray-integration method as a plain function of one segment, in
// double precision (the GLSL versions in Shaders/PsiIntegrate*.glsl follow the same formulas in
// float), and the table of methods (IntegrationMethodTable) that the mapper, the panel, the tests
// and the benchmarks all read. Equation and section numbers refer to Moreland's 2004
// dissertation ("Fast High Accuracy Volume Rendering") unless another paper is named.
//
// Two optical models are in play:
//  - linear attenuation (methods 1-3, 7): tau linear along the segment, tau = opacity / unit
//    distance (VTK's convention), the model of psi::IntegrateReference;
//  - linear opacity (methods 4-6, Moreland 2004 dissertation §5.3): alpha linear along the
//    segment, where alpha is the opacity of one unit distance and tau = -ln(1 - alpha) / unit
//    (Eq. 5.12), the model of psi::IntegrateReferenceLinearOpacity.
// Each method is measured against the reference of the model it approximates.
//
// Adding a method: one row of the table in PsiIntegrationMethods.cxx (with its psi::Method value,
// its CPU integrator and its error bound) and one Shaders/PsiIntegrate<Name>.glsl file defining
// integrateSegment(); the panel lists it once the <Entry> of the IntegrationMethod enumeration in
// XML/PsiVolumeRepresentation.xml names it (TestIntegrationMethods checks the two agree).
#ifndef PsiIntegrationMethods_h
#define PsiIntegrationMethods_h

#include "PsiIntegration.h"
#include "PsiVolumeCoreModule.h"

#include <string>
#include <vector>

namespace psi
{

struct PartialPreIntegrationTable;

/// The integration methods; the value is the IntegrationMethod property's value (the XML
/// enumeration) and the row of IntegrationMethodTable().
enum class Method
{
  Average = 0,                       ///< 1. average luminance and attenuation (§3.2.2, Eq. 3.16)
  PartialPreIntegration = 1,         ///< 2. Psi table (§5.2; Moreland & Angel 2004)
  LinearExact = 2,                   ///< 3. Williams, Max & Stein 1998 (§3.2.3, Eq. 3.28)
  AverageOpacity = 3,                ///< 4. average luminance and opacity (Wilhelms-van Gelder)
  LinearLuminanceAverageOpacity = 4, ///< 5. §5.3.1, Appendix B.5
  LinearOpacityImproved = 5,         ///< 6. §5.3.2, Eqs. 5.13-5.14, Appendix B.6
  FullPreIntegration = 6,            ///< 7. Röttger et al. 2000, 3D table per transfer function
  Count = 7                          ///< number of rows of IntegrationMethodTable()
};

/// The optical model a method approximates, hence the reference it is measured against.
enum class OpticalModel
{
  LinearAttenuation, ///< tau linear (psi::IntegrateReference)
  LinearOpacity      ///< alpha of one unit distance linear (psi::IntegrateReferenceLinearOpacity)
};

/// A segment given by transfer-function values at its ends: luminance and, in `a`, the opacity
/// function's value (in [0, 1]); D in world units; unit = ScalarOpacityUnitDistance.
struct TFSegment
{
  Rgb Lf{ { 0, 0, 0 } }, Lb{ { 0, 0, 0 } };
  double af = 0, ab = 0;
  double D = 0;
  double unit = 1;
};

/// CPU integrator of one segment in double precision. `psiTable` may be null (exact Psi then).
using SegmentIntegrator = Rgba (*)(const TFSegment& s, const PartialPreIntegrationTable* psiTable);

/// One row of the table of integration methods.
struct IntegrationMethodInfo
{
  Method Id;
  /// The panel text: exactly the <Entry text> of XML/PsiVolumeRepresentation.xml.
  const char* Name;
  /// Base name of the GLSL integrator: Shaders/<GlslName>.glsl, which defines
  /// `vec4 integrateSegment(float sf, float sb, float D)` (see psi::IntegratorGlslSource).
  const char* GlslName;
  /// GPU tables the GLSL integrator samples: the Psi table (uniform psiTable), Röttger's
  /// pre-integration table (uniform preIntegrated).
  bool NeedsPsiTable;
  bool NeedsPreIntegrationTable;
  OpticalModel Model;
  /// The CPU version (for FullPreIntegration: the exact value the table approximates).
  SegmentIntegrator Integrate;
  /// What the method promises: its largest error against its model's exact reference over
  /// Moreland's sweeps (dissertation Figs. 6.5-6.11) and the hard cases, which
  /// TestIntegrationMethods checks.
  double SweepErrorBound;
  /// The paper and section the method comes from.
  const char* Reference;
};

/// Every method, one row each, row i has Id == Method(i).
PSIVOLUMECORE_EXPORT const std::vector<IntegrationMethodInfo>& IntegrationMethodTable();
PSIVOLUMECORE_EXPORT int NumberOfIntegrationMethods();
/// The row of `m`; for a value outside the table, a row named "Unknown" whose integrator
/// returns zero and which needs no table.
PSIVOLUMECORE_EXPORT const IntegrationMethodInfo& GetIntegrationMethodInfo(Method m);
/// The row of method number `method` (a shader feature's or the XML's number).
inline const IntegrationMethodInfo& GetIntegrationMethodInfo(int method)
{
  return GetIntegrationMethodInfo(static_cast<Method>(method));
}
/// The row of an IntegrationMethod property value, or null outside the table.
PSIVOLUMECORE_EXPORT const IntegrationMethodInfo* FindIntegrationMethod(int value);
/// The row whose panel name is `name` (exact match), or null.
PSIVOLUMECORE_EXPORT const IntegrationMethodInfo* FindIntegrationMethod(const std::string& name);

/// GetIntegrationMethodInfo(m).Name ("Unknown" outside the table).
PSIVOLUMECORE_EXPORT const char* MethodName(Method m);
/// True for the methods of the linear-opacity model (4-6).
PSIVOLUMECORE_EXPORT bool UsesLinearOpacity(Method m);

/// Segment for the linear-attenuation model: tau = a / unit.
PSIVOLUMECORE_EXPORT Segment AttenuationSegment(const TFSegment& s);

/// Psi in closed form (Williams, Max & Stein 1998; Moreland 2004 dissertation Eq. 3.28), with
/// erfcx and Dawson's integral evaluated stably (Numerical Recipes' erfc fit, Eq. 3.24, and
/// Rybicki's method), and a series in (tau_b - tau_f) D where the closed form cancels.
PSIVOLUMECORE_EXPORT double PsiClosedForm(double taubD, double taufD);
PSIVOLUMECORE_EXPORT double Erfcx(double x);  ///< e^{x^2} erfc(x), x >= 0
PSIVOLUMECORE_EXPORT double Dawson(double x); ///< e^{-x^2} int_0^x e^{t^2} dt

/// One segment by `m` (the row's integrator). For PartialPreIntegration `psiTable` is looked up
/// when given (exact Psi otherwise); for FullPreIntegration, the pre-integration table (see
/// PsiPreIntegrationTable.h) is used by the caller instead, so this function evaluates it exactly
/// (the limit of an infinitely fine table).
PSIVOLUMECORE_EXPORT Rgba Integrate(
  Method m, const TFSegment& s, const PartialPreIntegrationTable* psiTable = nullptr);

} // namespace psi

#endif
