//VTK::System::Dec
//PSI::Stage::Extensions
//PSI::Counts::Dec
// PsiVolumeGS: projects one tetrahedron and emits its Shirley-Tuchman decomposition
// (1-4 triangles, Maximo et al. 2010 §3.2) carrying front scalar, back scalar and thickness.
//
// This is the template of the geometry shader. psi::ComposeShaders (PsiShaderComposer.cxx)
// replaces each `//PSI::<Feature>::<Site>` tag with the section of that name in the feature's
// file (PsiProjectionClassesGS.glsl, PsiExactSegmentsGS.glsl, PsiNearClipGS.glsl, ...), or with
// nothing when the scene does not call for the feature. PSI_GS_MAX_VERTICES (and PSI_ISO_COUNT
// with isosurfaces) come from //PSI::Counts::Dec.
//
// Screen-space positions are interpolated back into 3D with perspective-correct weights
// (lambda_i / w_i). Thin vertices carry (s, s, 0); the thick vertex carries
// (s_front, s_back, length).
//
// psi::ComposeShaders writes this stage in one of two forms (PsiStageInterface.cxx): a geometry
// shader, or the function psiGeometryMain of the compute-shader projector (PsiProjectCS.glsl).
// The form's declarations replace //PSI::Stage::Dec: tetIn[0], the tetrahedron from the vertex
// code; the outputs each feature writes per vertex (psi::GeometryOutputs); and
// psiEmitVertex(position) / psiEndPrimitive(), which end a vertex and a strip.

//PSI::Stage::Dec
//PSI::Stage::Emit

uniform mat4 VCDCMatrix;
uniform int parallelProjection;

vec4 clipP[4] = vec4[4](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
vec3 viewP[4] = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
float scalar[4] = float[4](0.0, 0.0, 0.0, 0.0);
vec2 ndc[4] = vec2[4](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));

vec3 thickFront = vec3(0.0);
vec3 thickSeg = vec3(0.0);

//PSI::CellGradient::Dec
//PSI::SeparateOpacity::Dec
//PSI::HAPTSegments::Dec
//PSI::ExactSegments::Dec
//PSI::RaySegments::Dec
//PSI::EarlyDiscard::Dec
//PSI::NearClip::Dec
//PSI::IsoFlatNormals::Dec
//PSI::IsoSmoothNormals::Dec
//PSI::IsoPerFragment::Dec
//PSI::IsoTriangles::Dec
//PSI::ProjectionClasses::Dec

float cross2(vec2 a, vec2 b)
{
  return a.x * b.y - a.y * b.x;
}

// 3D point and scalar at screen-space parameter t along the projected edge a->b.
void alongEdge(int a, int b, float t, out vec3 p, out float s)
{
  float wa = clipP[a].w, wb = clipP[b].w;
  float tc = (t / wb) / ((1.0 - t) / wa + t / wb); // perspective-correct parameter
  p = mix(viewP[a], viewP[b], tc);
  s = mix(scalar[a], scalar[b], tc);
}

// Parameter of the projection of point m on projected edge a->b.
float edgeParam(int a, int b, int m)
{
  vec2 e = ndc[b] - ndc[a];
  return clamp(dot(ndc[m] - ndc[a], e) / max(dot(e, e), 1e-30), 0.0, 1.0);
}

// Eye distance along the ray (larger is farther). In parallel projection w is constant, so the
// view-space depth decides; in perspective the clip w is the view depth too.
float farness(vec3 p)
{
  return -p.z;
}

// The per-primitive (flat) outputs of the features, set before every vertex.
void setFlat(int isClipped)
{
//PSI::IsoPerFragment::Flat
//PSI::IsoTriangles::Flat
//PSI::NearClip::Flat
}

void emitThin(int i)
{
  setFlat(0);
  setVertexSegment(viewP[i], vec3(scalar[i], scalar[i], 0.0));
  psiEmitVertex(clipP[i]);
}

void emitThick()
{
  setFlat(0);
  setVertexSegment(thickFront, thickSeg);
  psiEmitVertex(VCDCMatrix * vec4(thickFront, 1.0));
}

// Orders the two ends of the thick ray segment into front and back.
void setThick(vec3 pa, float sa, vec3 pb, float sb)
{
  float len = distance(pa, pb);
  if (farness(pa) <= farness(pb))
  {
    thickFront = pa;
    thickSeg = vec3(sa, sb, len);
  }
  else
  {
    thickFront = pb;
    thickSeg = vec3(sb, sa, len);
  }
}

//PSI::NearClip::Impl
//PSI::ProjectionClasses::Impl
//PSI::HAPTSegments::Emit
//PSI::ExactSegments::Emit
//PSI::RaySegments::Emit

// The cell's volume: projected, or as a screen box when the near plane cuts it.
void emitVolume(bool nearClipped)
{
//PSI::NearClip::Volume
  emitProjection();
}

//PSI::IsoTriangles::Impl

void psiGeometryMain()
{
  vec4 raw[4] = tetIn[0].points;
  float smin = min(min(raw[0].w, raw[1].w), min(raw[2].w, raw[3].w));
  float smax = max(max(raw[0].w, raw[1].w), max(raw[2].w, raw[3].w));
  float dmin = smin, dmax = smax; // the scalar range that decides early discard
//PSI::SeparateOpacity::Range
//PSI::EarlyDiscard::Cell
  int inFront = 0;
  for (int i = 0; i < 4; ++i)
  {
    viewP[i] = raw[i].xyz;
    scalar[i] = raw[i].w;
//PSI::NearClip::Count
  }
//PSI::CellGradient::Impl
//PSI::IsoPerFragment::Impl
  bool nearClipped = false;
//PSI::NearClip::Cull
  if (!nearClipped)
  {
    for (int i = 0; i < 4; ++i)
    {
      clipP[i] = VCDCMatrix * vec4(viewP[i], 1.0);
      if (clipP[i].w <= 0.0)
      {
        return; // behind the eye; only reachable without near clipping, which the mapper prevents
      }
      ndc[i] = clipP[i].xy / clipP[i].w;
    }
    classify();
  }
//PSI::IsoTriangles::Emit
  emitVolume(nearClipped);
}
//PSI::Stage::Main
