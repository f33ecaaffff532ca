// PsiIntegratorSources: the GLSL integrators Shaders/PsiIntegrate*.glsl, embedded at build time
// (Rendering/CMakeLists.txt globs them and generates PsiIntegratorSources.cxx), looked up
// by the GLSL base name of a row of psi::IntegrationMethodTable() (PsiIntegrationMethods.h).
// Each file defines `vec4 integrateSegment(float sf, float sb, float D)` and replaces
// //PSI::Integrator::Impl in PsiVolumeFS.glsl.
#ifndef PsiIntegratorSources_h
#define PsiIntegratorSources_h

#include "PsiVolumeRenderingModule.h"

#include <string>
#include <vector>

namespace psi
{
/// The source of Shaders/<baseName>.glsl (e.g. "PsiIntegrateAverage"), or null if no such
/// integrator was embedded.
PSIVOLUMERENDERING_EXPORT const char* IntegratorGlslSource(const char* baseName);

/// The base names of every embedded Shaders/PsiIntegrate*.glsl, sorted.
PSIVOLUMERENDERING_EXPORT const std::vector<std::string>& IntegratorGlslNames();
} // namespace psi

#endif
