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
flat in ivec4 clipTet; // point ids of a cell cut by the near plane, x = -1 otherwise
uniform samplerBuffer points; // xyz: model coordinates (shifted), w: scalar
uniform mat4 MCVCMatrix;

vec4 clipVertex(int id)
{
  vec4 p = texelFetch(points, id);
  return vec4((MCVCMatrix * vec4(p.xyz, 1.0)).xyz, p.w);
}
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

#ifdef PSI_ISO_COUNT
uniform vec3 isoColors[PSI_ISO_COUNT];
uniform float isoOpacities[PSI_ISO_COUNT]; // each surface's own
uniform int isoLighting;
uniform int lightCount;
uniform vec3 lightDirVC[PSI_MAX_LIGHTS]; // direction the light travels, view coordinates
uniform vec3 lightColor[PSI_MAX_LIGHTS]; // diffuse color * intensity

// Premultiplied color of isosurface i with normal n (any length), seen along dir: two-sided
// diffuse lighting with the renderer's lights (VTK's Phong without ambient and specular:
// ParaView's defaults).
vec4 isoShade(int i, vec3 n, vec3 dir)
{
  vec3 c = isoColors[i];
  if (isoLighting == 1)
  {
    float nn = dot(n, n);
    n = nn > 1e-37 ? n * inversesqrt(nn) : -dir;
    n = dot(n, dir) > 0.0 ? -n : n;
    vec3 lit = vec3(0.0);
    for (int k = 0; k < lightCount; ++k)
    {
      lit += lightColor[k] * max(dot(n, -lightDirVC[k]), 0.0);
    }
    c *= lit;
  }
  return vec4(c * isoOpacities[i], isoOpacities[i]);
}
#endif

#ifdef PSI_ISO_TRIANGLES
// Marching-tetrahedra isosurfaces from the geometry shader: a volume fragment integrates only
// the part of its segment inside its piece's scalar interval [lo, hi); a surface fragment is the
// lit surface (normal interpolated from the polygon's vertices).
flat in float piece; // see PsiVolumeGS.glsl: >= 0 a volume piece, < 0 a surface
uniform float isoValues[PSI_ISO_COUNT]; // ascending

bool clipToPiece(inout float sf, inout float sb, inout float D)
{
  int j = int(piece + 0.5);
  if (j > PSI_ISO_COUNT)
  {
    return true; // the whole cell
  }
  const float big = 3.0e38;
  vec2 range = vec2(j > 0 ? isoValues[j - 1] : -big, j < PSI_ISO_COUNT ? isoValues[j] : big);
  float ds = sb - sf;
  if (ds == 0.0)
  {
    return sf >= range.x && sf < range.y;
  }
  float ta = clamp((range.x - sf) / ds, 0.0, 1.0), tb = clamp((range.y - sf) / ds, 0.0, 1.0);
  float t0 = min(ta, tb), t1 = max(ta, tb);
  if (!(t1 > t0))
  {
    return false;
  }
  float s0 = sf + t0 * ds, s1 = sf + t1 * ds;
  sf = s0;
  sb = s1;
  D *= t1 - t0;
  return true;
}
#endif

#if defined(PSI_ISO_PER_FRAGMENT) || defined(PSI_ADAPTIVE)
// Segments split into pieces (issue 5), integrated and composited front to back in this
// fragment: at transfer-function nodes (adaptive sampling, Moreland §4.3: color and attenuation
// are linear on each piece) and, for per-fragment isosurfaces, at isovalue crossings, where the
// lit surface is composited at its depth (Roettger et al. §10: the part in front, the surface,
// the part behind). An isovalue counts on [front, back) of a segment, so that a crossing on a
// face shared by two cells is drawn once.
#ifdef PSI_ISO_PER_FRAGMENT
uniform float isoValues[PSI_ISO_COUNT]; // ascending
flat in vec3 isoG0;
flat in mat3 isoJ;
flat in vec3 isoV0;

// Isosurface i at view point p: the normal from the linear gradient field of the cell.
vec4 isoSurface(int i, vec3 p, vec3 dir)
{
  return isoShade(i, isoG0 + isoJ * (p - isoV0), dir);
}
#define PSI_ISO_SPLITS PSI_ISO_COUNT
#else
#define PSI_ISO_SPLITS 0
#endif

#ifdef PSI_ADAPTIVE
uniform float tfNodes[PSI_TF_NODES_MAX]; // ascending, strictly inside the scalar range
uniform int tfNodeCount;
#define PSI_TF_SPLITS PSI_TF_NODES_MAX
#else
#define PSI_TF_SPLITS 0
#endif

vec4 splitAcc;
void addPiece(float sa, float sb, float D)
{
  if (D > 0.0)
  {
    splitAcc += (1.0 - splitAcc.a) * integrateSegment(sa, sb, D);
  }
}

// p0, dir: view-space front point and unit ray direction (isosurface shading only).
vec4 integrateSplit(float sf, float sb, float D, vec3 p0, vec3 dir)
{
  splitAcc = vec4(0.0);
  float ds = sb - sf;
  float dirS = ds >= 0.0 ? 1.0 : -1.0;
  float sPrev = sf, tPrev = 0.0;
#ifdef PSI_ADAPTIVE
  int nStep = ds >= 0.0 ? 1 : -1;
  int ni = ds >= 0.0 ? 0 : tfNodeCount - 1;
  while (ni >= 0 && ni < tfNodeCount && dirS * (tfNodes[ni] - sf) <= 0.0)
  {
    ni += nStep;
  }
#endif
#ifdef PSI_ISO_PER_FRAGMENT
  int iStep = ds >= 0.0 ? 1 : -1;
  int ii = ds >= 0.0 ? 0 : PSI_ISO_COUNT - 1;
  while (ii >= 0 && ii < PSI_ISO_COUNT && dirS * (isoValues[ii] - sf) < 0.0)
  {
    ii += iStep;
  }
#endif
  for (int guard = 0; guard <= PSI_ISO_SPLITS + PSI_TF_SPLITS; ++guard)
  {
    float next = sb;
    int kind = 0;
#ifdef PSI_ADAPTIVE
    if (ni >= 0 && ni < tfNodeCount && dirS * (sb - tfNodes[ni]) > 0.0)
    {
      next = tfNodes[ni];
      kind = 1;
    }
#endif
#ifdef PSI_ISO_PER_FRAGMENT
    if (ii >= 0 && ii < PSI_ISO_COUNT && dirS * (sb - isoValues[ii]) > 0.0 &&
      dirS * (next - isoValues[ii]) >= 0.0)
    {
      next = isoValues[ii];
      kind = 2;
    }
#endif
    // kind != 0 implies ds != 0: no division by zero, no NaN
    float t = kind == 0 ? 1.0 : clamp((next - sf) / ds, tPrev, 1.0);
    addPiece(sPrev, next, (t - tPrev) * D);
    if (kind == 0)
    {
      break;
    }
#ifdef PSI_ADAPTIVE
    if (kind == 1)
    {
      ni += nStep;
    }
#endif
#ifdef PSI_ISO_PER_FRAGMENT
    if (kind == 2)
    {
      splitAcc += (1.0 - splitAcc.a) * isoSurface(ii, p0 + (t * D) * dir, dir);
      ii += iStep;
      if (splitAcc.a >= 1.0)
      {
        break; // an opaque isosurface stops the ray
      }
    }
#endif
    sPrev = next;
    tPrev = t;
  }
  return splitAcc;
}
#endif

vec3 viewPointAt(float depth)
{
  vec4 ndc = vec4(2.0 * gl_FragCoord.xy / viewportSize - 1.0, 2.0 * depth - 1.0, 1.0);
  vec4 p = DCVCMatrix * ndc;
  return p.xyz / p.w;
}

#ifdef PSI_NEAR_CLIP
// Exact ray / tetrahedron intersection for a cell cut by the near plane: the ray starts on the
// near plane at this pixel; each face plane bounds the parameter interval [tin, tout].
bool clipSegment(out float sf, out float sb, out float D, out float frontDepth, out vec3 pFront,
  out vec3 rayDir)
{
  vec4 tetV0 = clipVertex(clipTet.x), tetV1 = clipVertex(clipTet.y);
  vec4 tetV2 = clipVertex(clipTet.z), tetV3 = clipVertex(clipTet.w);
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
  pFront = pf;
  rayDir = dir;
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
#ifdef PSI_ISO_TRIANGLES
  if (piece < 0.0)
  {
    // An isosurface fragment (hidden by opaque geometry through the depth test).
    vec3 p = viewPointAt(gl_FragCoord.z);
    vec3 dir = parallelProjection == 1 ? vec3(0.0, 0.0, -1.0) : normalize(p);
#ifdef PSI_EXACT_SEGMENTS
    vec3 n = frontPoint.xyz;
#else
    vec3 n = segment;
#endif
    gl_FragData[0] = isoShade(int(-piece - 0.5), n, dir);
    return;
  }
#endif
  float sf, sb, D;
#ifdef PSI_EXACT_SEGMENTS
  exactSegment(sf, sb, D);
#else
  sf = segment.x;
  sb = segment.y;
  D = segment.z;
#endif
  float frontDepth = gl_FragCoord.z;
  vec3 pFront = vec3(0.0), rayDir = vec3(0.0, 0.0, -1.0);
#ifdef PSI_ISO_PER_FRAGMENT
#ifdef PSI_EXACT_SEGMENTS
  pFront = frontPoint.xyz;
  rayDir = normalize(frontPoint.xyz);
#else
  pFront = viewPointAt(gl_FragCoord.z);
  rayDir = parallelProjection == 1 ? vec3(0.0, 0.0, -1.0) : normalize(pFront);
#endif
#endif
#ifdef PSI_NEAR_CLIP
  if (clipTet.x >= 0 && !clipSegment(sf, sb, D, frontDepth, pFront, rayDir))
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
#ifdef PSI_ISO_TRIANGLES
  if (!clipToPiece(sf, sb, D))
  {
    discard;
  }
#endif
#if defined(PSI_ISO_PER_FRAGMENT) || defined(PSI_ADAPTIVE)
  vec4 c = integrateSplit(sf, sb, max(D, 0.0), pFront, rayDir);
#else
  vec4 c = integrateSegment(sf, sb, max(D, 0.0));
#endif
  if (!(c.a > 0.0))
  {
    discard; // fully transparent, or a NaN that must not reach the image
  }
  gl_FragData[0] = c;
}
