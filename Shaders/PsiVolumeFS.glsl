//VTK::System::Dec
//PSI::Features::Dec
//VTK::Output::Dec
// PsiVolumeFS: integrates the ray segment through one tetrahedron (front scalar, back scalar,
// thickness interpolated from the geometry shader) and outputs premultiplied color, blended
// back to front with (ONE, ONE_MINUS_SRC_ALPHA) into a floating-point target.

#ifndef PSI_EXACT_SEGMENTS
noperspective in vec3 segment; // front scalar, back scalar, thickness (HAPT)
#endif

uniform sampler2D transferFunction; // N x 1, rgb = luminance, a = attenuation (1/length)
uniform vec2 tfScaleShift;          // texcoord = s * scale + shift (texel centers)
uniform sampler2D psiTable;         // Psi(gamma_b, gamma_f), seed 000 Eq. 12
uniform vec2 psiScaleShift;         // texcoord = u * scale + shift (texel centers)
uniform float unitDistance;        // ScalarOpacityUnitDistance (linear-opacity methods)
uniform sampler3D preIntegrated;    // full pre-integration table (Roettger)
uniform vec2 preScalarScaleShift;
uniform vec2 preLengthScaleShift;
uniform sampler2D sceneDepth;       // depth of the opaque geometry (PSI_OPAQUE_CLIP, PSI_NEAR_CLIP)
uniform mat4 DCVCMatrix;            // inverse projection: window depth -> view distance
uniform vec2 viewportSize;
uniform mat4 VCDCMatrix;
uniform int parallelProjection;

#ifdef PSI_EXACT_SEGMENTS
smooth in vec4 frontPoint;
flat in vec4 backPlane;
flat in vec4 scalarGrad;
#endif

#ifdef PSI_NEAR_CLIP
flat in int clipped;
flat in vec4 tetV0;
flat in vec4 tetV1;
flat in vec4 tetV2;
flat in vec4 tetV3;
#endif

vec4 transfer(float s)
{
  return texture(transferFunction, vec2(s * tfScaleShift.x + tfScaleShift.y, 0.5));
}

// Psi table coordinate of (tau_b D, tau_f D): gamma = tau D / (tau D + 1) (seed 000 Eq. 11),
// warped to u = 1 - sqrt(1 - gamma) = 1 - 1/sqrt(tau D + 1) so that the sqrt(1 - gamma) edge
// behavior of Psi is linear in the table (PsiTable.h). tau D = inf gives u = 1, not NaN.
vec2 psiCoord(vec2 tauD)
{
  return (1.0 - inversesqrt(tauD + 1.0)) * psiScaleShift.x + psiScaleShift.y;
}

//PSI::Integrator::Impl

vec3 viewPointAt(float depth)
{
  vec4 ndc = vec4(2.0 * gl_FragCoord.xy / viewportSize - 1.0, 2.0 * depth - 1.0, 1.0);
  vec4 p = DCVCMatrix * ndc;
  return p.xyz / p.w;
}

#ifdef PSI_NEAR_CLIP
// Exact ray / tetrahedron intersection for a cell cut by the near plane: the ray starts on the
// near plane at this pixel; each face plane bounds the parameter interval [tin, tout].
bool clipSegment(out float sf, out float sb, out float D, out float frontDepth)
{
  vec3 V[4] = vec3[4](tetV0.xyz, tetV1.xyz, tetV2.xyz, tetV3.xyz);
  vec3 o = viewPointAt(0.0);
  vec3 dir = parallelProjection == 1 ? vec3(0.0, 0.0, -1.0) : normalize(o);
  float tin = 0.0, tout = 1e30;
  for (int i = 0; i < 4; ++i)
  {
    vec3 a = V[(i + 1) % 4], b = V[(i + 2) % 4], c = V[(i + 3) % 4];
    vec3 n = cross(b - a, c - a);
    if (dot(n, V[i] - a) > 0.0)
    {
      n = -n; // outward
    }
    float den = dot(n, dir);
    float num = dot(n, a - o);
    if (abs(den) < 1e-30)
    {
      if (num < 0.0)
      {
        return false; // parallel to the face and outside it
      }
      continue;
    }
    float t = num / den;
    if (den < 0.0)
    {
      tin = max(tin, t);
    }
    else
    {
      tout = min(tout, t);
    }
  }
  if (!(tout > tin))
  {
    return false;
  }
  // Linear scalar: s(x) = s0 + g . (x - V0), g from the three edge equations.
  mat3 E = mat3(V[1] - V[0], V[2] - V[0], V[3] - V[0]);
  vec3 ds = vec3(tetV1.w - tetV0.w, tetV2.w - tetV0.w, tetV3.w - tetV0.w);
  vec3 g = inverse(transpose(E)) * ds;
  vec3 pf = o + tin * dir, pb = o + tout * dir;
  sf = tetV0.w + dot(g, pf - V[0]);
  sb = tetV0.w + dot(g, pb - V[0]);
  D = tout - tin;
  vec4 c = VCDCMatrix * vec4(pf, 1.0);
  frontDepth = 0.5 * c.z / c.w + 0.5;
  return true;
}
#endif

#ifdef PSI_EXACT_SEGMENTS
// Exact segment in perspective: the ray from the eye through the (exactly interpolated) front
// point leaves through the back plane.
void exactSegment(out float sf, out float sb, out float D)
{
  vec3 dir = normalize(frontPoint.xyz);
  D = (backPlane.w - dot(backPlane.xyz, frontPoint.xyz)) / dot(backPlane.xyz, dir);
  D = clamp(D, 0.0, scalarGrad.w); // guards grazing rays at a silhouette edge
  sf = frontPoint.w;
  sb = sf + D * dot(scalarGrad.xyz, dir);
}
#endif

void main()
{
  float sf, sb, D;
#ifdef PSI_EXACT_SEGMENTS
  exactSegment(sf, sb, D);
#else
  sf = segment.x;
  sb = segment.y;
  D = segment.z;
#endif
  float frontDepth = gl_FragCoord.z;
#ifdef PSI_NEAR_CLIP
  if (clipped == 1 && !clipSegment(sf, sb, D, frontDepth))
  {
    discard;
  }
#endif
  // Fragments behind opaque geometry are rejected by the depth test against the scene's depth.
  // Where opaque geometry cuts through the volume, a cell it cuts is integrated only up to it.
#if defined(PSI_OPAQUE_CLIP) || defined(PSI_NEAR_CLIP)
  float opaque = texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r;
  if (frontDepth >= opaque)
  {
    discard;
  }
#endif
#ifdef PSI_OPAQUE_CLIP
  if (opaque < 1.0)
  {
    float toOpaque = distance(viewPointAt(frontDepth), viewPointAt(opaque));
    if (toOpaque < D)
    {
      sb = mix(sf, sb, toOpaque / max(D, 1e-30));
      D = toOpaque;
    }
  }
#endif
  vec4 c = integrateSegment(sf, sb, max(D, 0.0));
  if (!(c.a > 0.0))
  {
    discard; // fully transparent, or a NaN that must not reach the image
  }
  gl_FragData[0] = c;
}
