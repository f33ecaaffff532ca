// TEMPORARY shim (replaced by the composer of the shader split): the feature set of a program.
#ifndef PsiShaderComposer_h
#define PsiShaderComposer_h
#include <string>
namespace psi
{
struct ShaderFeatures
{
  int Method = 1;
  bool ExactSegments = false;
  bool NearClip = false;
  bool OpaqueClip = false;
  bool EarlyDiscard = false;
  int IsoCount = 0;
  bool IsoSmooth = false;
  bool IsoTriangles = false;
  bool Adaptive = false;
  int MaxAdaptiveNodes = 64;
  int MaxLights = 8;
  std::string Key() const;
};
bool FitsGeometryOutputLimits(const ShaderFeatures& f, int maxVertices, int maxTotalComponents);
struct ShaderSources
{
  std::string Vertex, Geometry, Fragment;
};
ShaderSources ComposeShaders(const ShaderFeatures& f, const char* integratorSource);
}
#endif
