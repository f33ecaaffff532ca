#include "PsiShaderFeatures.h"

namespace psi
{
namespace
{
std::string Define(const char* name, int value)
{
  return std::string("#define ") + name + " " + std::to_string(value) + "\n";
}
} // namespace

bool DepthPeelDrawn(const ShaderFeatures& f)
{
  return f.DepthPeel && f.Silhouette;
}

int GeometryOutputVertices(const ShaderFeatures& f)
{
  // PsiProjectionClassesGS.glsl: the fan of class 2, strips of 5 and 3; a silhouette quad
  const int projection = f.Silhouette ? 4 : 8;
  const int surface = 4; // PsiIsoTrianglesGS.glsl emitSurface: a strip of at most 4
  if (f.IsoCount > 0 && f.IsoTriangles)
  {
    return projection * (f.IsoCount + 1) + surface * f.IsoCount;
  }
  return projection;
}

int ProjectedTrianglesMax(const ShaderFeatures& f)
{
  // class 2: four triangles (Shirley & Tuchman's largest split); a silhouette quad has two
  const int projection = f.Silhouette ? 2 : 4;
  const int surface = 2; // a marching-tetrahedra quad
  if (f.IsoCount > 0 && f.IsoTriangles)
  {
    return projection * (f.IsoCount + 1) + surface * f.IsoCount;
  }
  return projection;
}

bool SeparateOpacityDrawn(const ShaderFeatures& f)
{
  return f.SeparateOpacity && f.Silhouette && !f.Adaptive;
}

bool ShaderFeatures::operator==(const ShaderFeatures& o) const
{
  return Method == o.Method && ExactSegments == o.ExactSegments && Silhouette == o.Silhouette &&
    NearClip == o.NearClip && OpaqueClip == o.OpaqueClip && EarlyDiscard == o.EarlyDiscard &&
    IsoCount == o.IsoCount && IsoSmooth == o.IsoSmooth && IsoTriangles == o.IsoTriangles &&
    Adaptive == o.Adaptive && SeparateOpacity == o.SeparateOpacity && DepthPeel == o.DepthPeel &&
    MaxAdaptiveNodes == o.MaxAdaptiveNodes && MaxLights == o.MaxLights &&
    RasterFloor == o.RasterFloor;
}

std::string ShaderFeatures::Defines() const
{
  std::string d;
  if (OpaqueClip)
  {
    d += "#define PSI_OPAQUE_CLIP\n";
  }
  if (Silhouette)
  {
    d += "#define PSI_SILHOUETTE\n";
  }
  else if (ExactSegments)
  {
    d += "#define PSI_EXACT_SEGMENTS\n";
  }
  if (NearClip)
  {
    d += "#define PSI_NEAR_CLIP\n";
  }
  if (IsoCount > 0)
  {
    d += Define("PSI_ISO_COUNT", IsoCount) + Define("PSI_MAX_LIGHTS", MaxLights);
    if (IsoSmooth)
    {
      d += "#define PSI_ISO_SMOOTH\n";
    }
    d += IsoTriangles
      ? "#define PSI_ISO_TRIANGLES\n" + Define("PSI_GS_MAX_VERTICES", GeometryOutputVertices(*this))
      : std::string("#define PSI_ISO_PER_FRAGMENT\n");
  }
  if (EarlyDiscard)
  {
    d += "#define PSI_EARLY_DISCARD\n";
  }
  if (SeparateOpacityDrawn(*this))
  {
    d += "#define PSI_SEPARATE_OPACITY\n";
  }
  if (DepthPeelDrawn(*this))
  {
    d += "#define PSI_DEPTH_PEEL\n";
  }
  if (Adaptive)
  {
    d += "#define PSI_ADAPTIVE\n" + Define("PSI_TF_NODES_MAX", MaxAdaptiveNodes);
  }
  if (RasterFloor)
  {
    d += "#define PSI_RASTER_FLOOR\n";
  }
  return d;
}

std::string ShaderFeatures::Key() const
{
  return this->Defines() + "method " + std::to_string(Method) + "\n";
}

} // namespace psi
