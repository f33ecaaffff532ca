//VTK::System::Dec
//PSI::Features::Dec
// PsiVolumeGS: projects one tetrahedron and emits its Shirley-Tuchman decomposition
// (1-4 triangles, HAPT seed 002 §3.2) carrying front scalar, back scalar and thickness.
//
// Classification: the four orientation tests of PTINT (Marroquim et al., seed 003 Fig. 3) index
// the 81-entry ternary truth table, derived and tested on the CPU (PsiProjectionClasses.cxx) and
// passed as `classTable`: entry = class | p0<<4 | p1<<6 | p2<<8 | p3<<10.
//   class 1: p3 inside triangle p0 p1 p2          -> fan of 3 around p3      (thick vertex p3)
//   class 2: segment p0p1 crosses segment p2p3    -> fan of 4 around the crossing
//   class 3: p3 on segment p0p1                    -> fan of 2 around p3
//   class 4: p2 and p3 project to the same point   -> 1 triangle, thick vertex p2/p3
// Thin vertices carry (s, s, 0); the thick vertex carries (s_front, s_back, length). Screen-space
// positions are interpolated back into 3D with perspective-correct weights (lambda_i / w_i).

layout(points) in;
#ifndef PSI_GS_MAX_VERTICES
#define PSI_GS_MAX_VERTICES 8 // the largest decomposition (class 2: a strip of 5 and one of 3)
#endif
layout(triangle_strip, max_vertices = PSI_GS_MAX_VERTICES) out;

in vec4 vsP0[];
in vec4 vsP1[];
in vec4 vsP2[];
in vec4 vsP3[];

uniform mat4 VCDCMatrix;

#ifdef PSI_EARLY_DISCARD
// HAPT §3.5: a tetrahedron whose scalar range meets only zero-opacity samples of the (linearly
// interpolated) transfer function contributes nothing and emits nothing. opacityPrefix[i] counts
// the samples 0..i with non-zero opacity.
uniform sampler2D opacityPrefix;
uniform vec2 tfIndexScaleShift; // scalar -> sample index
uniform int tfSamples;

bool transparentRange(float smin, float smax)
{
  int i0 = clamp(int(floor(smin * tfIndexScaleShift.x + tfIndexScaleShift.y)), 0, tfSamples - 1);
  int i1 = clamp(int(ceil(smax * tfIndexScaleShift.x + tfIndexScaleShift.y)), 0, tfSamples - 1);
  float before = i0 > 0 ? texelFetch(opacityPrefix, ivec2(i0 - 1, 0), 0).r : 0.0;
  return texelFetch(opacityPrefix, ivec2(i1, 0), 0).r - before < 0.5;
}
#endif
uniform int classTable[81];

#ifndef PSI_EXACT_SEGMENTS
noperspective out vec3 segment; // front scalar, back scalar, thickness
#endif

#ifdef PSI_EXACT_SEGMENTS
// Perspective: screen-linear interpolation of thickness is only approximate (it is exact in
// parallel projection, where HAPT's (s_f, s_b, l) triple is used). Every fan triangle lies in the
// tetrahedron's front face for its rays, so perspective-correct interpolation of the view-space
// front point and front scalar is exact; the rays leave through the other face sharing the
// triangle's thin edge a-b (the back plane), where one plane intersection per fragment gives the
// exact thickness and, with the scalar gradient, the back scalar.
smooth out vec4 frontPoint; // view-space xyz, w = scalar
flat out vec4 backPlane;    // n . x = w
flat out vec4 scalarGrad;   // xyz: gradient of the scalar, w: bound on the thickness
#endif
vec3 gradient; // of the scalar, view coordinates (exact segments and isosurfaces)

#ifdef PSI_NEAR_CLIP
// Tetrahedra that cross the near plane cannot be projected: they are drawn as a screen quad
// covering their near-clipped projection, and the fragment shader intersects each ray with the
// tetrahedron exactly. clipTet: the point ids (fetched by the fragment shader), x = -1 when not
// clipped; one output slot instead of four vertices keeps the geometry-shader output small.
uniform float nearZ; // view-space z of the near plane (negative)
flat out ivec4 clipTet;
#endif

#if defined(PSI_ISO_COUNT) || defined(PSI_NEAR_CLIP)
flat in uvec4 vsIds[];
#endif

#ifdef PSI_ISO_COUNT
// Isosurfaces (issue 5). The scalar is linear in the tetrahedron, so its isosurface there is the
// planar marching-tetrahedra polygon. Smooth shading uses the gradient field interpolated linearly
// from the smoothed point gradients (view coordinates); flat shading the cell's own gradient.
#ifdef PSI_ISO_SMOOTH
uniform samplerBuffer pointGradients; // model-space (shifted) gradient per point
uniform mat3 normalMatrix;            // model -> view for gradients (inverse transpose)
#endif
vec3 pointNormal[4];
#endif

#ifdef PSI_ISO_PER_FRAGMENT
// Per-fragment isosurfaces (HAPT §3.4's "per-pixel" strategy): the fragment shader meets the
// surface exactly along each ray; the normal field g(x) = isoG0 + isoJ (x - isoV0) is passed flat.
flat out vec3 isoG0;
flat out mat3 isoJ;
flat out vec3 isoV0;
vec3 tetIsoG0;
mat3 tetIsoJ;
#endif

#ifdef PSI_ISO_TRIANGLES
// On-the-fly marching tetrahedra (HAPT §3.4): each isosurface crossing the cell is emitted as one
// or two triangles, in visibility order with the volume: the cell is drawn once per scalar
// interval between its crossings ("piece"), the farthest first, each piece's fragments
// integrating only the part of their ray segment inside that interval, with the surface that
// bounds the piece on the eye's side drawn right after it (Roettger et al. §10: behind, surface,
// in front). Primitives emitted by one invocation are blended in emission order.
// Surface vertices carry their normal in frontPoint.xyz (perspective) or segment (parallel).
uniform float isoValues[PSI_ISO_COUNT]; // ascending
uniform int parallelProjection;
// piece (one component, to fit more isovalues in the geometry shader's output): j >= 0, the
// volume between isoValues[j - 1] and isoValues[j] (j = 0 .. PSI_ISO_COUNT, open-ended at the
// ends), j = PSI_ISO_COUNT + 1 the whole cell; -(i + 1): the surface of isovalue i.
flat out float piece;
float currentPiece = float(PSI_ISO_COUNT + 1);
#endif
vec4 clipP[4];
vec3 viewP[4];
float scalar[4];
vec2 ndc[4];

vec3 thickFront;
vec3 thickSeg;

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

#ifdef PSI_EXACT_SEGMENTS
vec4 facePlane(int a, int b, int c)
{
  vec3 n = cross(viewP[b] - viewP[a], viewP[c] - viewP[a]);
  return vec4(n, dot(n, viewP[a]));
}

float planeDistance(vec4 plane, vec3 p)
{
  return abs(dot(plane.xyz, p) - plane.w) * inversesqrt(max(dot(plane.xyz, plane.xyz), 1e-37));
}
#endif

// Flat data of the triangle completed by the next vertex (the provoking, last, vertex): of the
// two faces sharing its thin edge a-b, the one through the thick front point is the front face,
// the other the back face.
void setEdge(int a, int b)
{
#ifdef PSI_EXACT_SEGMENTS
  int c = 0;
  while (c == a || c == b)
  {
    ++c;
  }
  int d = 6 - a - b - c;
  vec4 fc = facePlane(a, b, c), fd = facePlane(a, b, d);
  backPlane = planeDistance(fc, thickFront) <= planeDistance(fd, thickFront) ? fd : fc;
  scalarGrad = vec4(gradient, 1.5 * thickSeg.z);
#endif
}

void setFlat(int isClipped)
{
#ifdef PSI_ISO_PER_FRAGMENT
  isoG0 = tetIsoG0;
  isoJ = tetIsoJ;
  isoV0 = viewP[0];
#endif
#ifdef PSI_ISO_TRIANGLES
  piece = currentPiece;
#endif
#ifdef PSI_NEAR_CLIP
  clipTet = isClipped == 1 ? ivec4(vsIds[0]) : ivec4(-1);
#endif
}

void emitThin(int i)
{
  setFlat(0);
#ifdef PSI_EXACT_SEGMENTS
  frontPoint = vec4(viewP[i], scalar[i]);
#else
  segment = vec3(scalar[i], scalar[i], 0.0);
#endif
  gl_Position = clipP[i];
  EmitVertex();
}

void emitThick()
{
  setFlat(0);
#ifdef PSI_EXACT_SEGMENTS
  frontPoint = vec4(thickFront, thickSeg.x);
#else
  segment = thickSeg;
#endif
  gl_Position = VCDCMatrix * vec4(thickFront, 1.0);
  EmitVertex();
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

#ifdef PSI_NEAR_CLIP
// Extends the screen box lo..hi by the projection of view-space point p (in front of the eye).
void includePoint(vec3 p, inout vec2 lo, inout vec2 hi)
{
  vec4 c = VCDCMatrix * vec4(p, 1.0);
  vec2 q = c.xy / c.w;
  lo = min(lo, q);
  hi = max(hi, q);
}

// Emits the screen box of the part of the tetrahedron beyond the near plane.
void emitClipped()
{
  vec2 lo = vec2(1e30), hi = vec2(-1e30);
  for (int i = 0; i < 4; ++i)
  {
    if (viewP[i].z <= nearZ)
    {
      includePoint(viewP[i], lo, hi);
    }
    for (int j = i + 1; j < 4; ++j)
    {
      float di = viewP[i].z - nearZ, dj = viewP[j].z - nearZ;
      if (di * dj < 0.0)
      {
        includePoint(mix(viewP[i], viewP[j], di / (di - dj)), lo, hi);
      }
    }
  }
  lo = max(lo, vec2(-1.0));
  hi = min(hi, vec2(1.0));
  if (lo.x > hi.x || lo.y > hi.y)
  {
    return;
  }
  vec2 corner[4] = vec2[4](lo, vec2(hi.x, lo.y), vec2(lo.x, hi.y), hi);
  for (int k = 0; k < 4; ++k)
  {
    setFlat(1);
#ifdef PSI_EXACT_SEGMENTS
    frontPoint = vec4(0.0);
#else
    segment = vec3(0.0);
#endif
    gl_Position = vec4(corner[k], -1.0, 1.0); // on the near plane: passes the depth test
    EmitVertex();
  }
  EndPrimitive();
}
#endif

#ifdef PSI_ISO_COUNT
// Isosurface normals at the four vertices.
void fetchNormals()
{
  for (int k = 0; k < 4; ++k)
  {
#ifdef PSI_ISO_SMOOTH
    pointNormal[k] = normalMatrix * texelFetch(pointGradients, int(vsIds[0][k])).xyz;
#else
    pointNormal[k] = gradient; // flat shading: the cell's gradient
#endif
  }
}
#endif

// Projection class and the four vertices in the class's order, from the truth table.
int cls, p0, p1, p2, p3;

// seed 003 Fig. 3: classifies the projection and computes the thick vertex's segment.
void classify()
{
  int t1 = int(sign(cross2(ndc[1] - ndc[0], ndc[2] - ndc[0]))) + 1;
  int t2 = int(sign(cross2(ndc[1] - ndc[0], ndc[3] - ndc[0]))) + 1;
  int t3 = int(sign(cross2(ndc[2] - ndc[0], ndc[3] - ndc[0]))) + 1;
  int t4 = int(sign(cross2(ndc[1] - ndc[2], ndc[1] - ndc[3]))) + 1;
  int entry = classTable[27 * t1 + 9 * t2 + 3 * t3 + t4];
  cls = entry & 15;
  p0 = (entry >> 4) & 3;
  p1 = (entry >> 6) & 3;
  p2 = (entry >> 8) & 3;
  p3 = (entry >> 10) & 3;
  if (cls == 1)
  {
    // Ray through p3 meets face p0 p1 p2: screen barycentrics, made perspective-correct.
    vec2 a = ndc[p0], b = ndc[p1], c = ndc[p2], m = ndc[p3];
    float area = cross2(b - a, c - a);
    vec3 l = vec3(cross2(b - m, c - m), cross2(c - m, a - m), cross2(a - m, b - m)) / area;
    l /= vec3(clipP[p0].w, clipP[p1].w, clipP[p2].w);
    l /= (l.x + l.y + l.z);
    vec3 h = l.x * viewP[p0] + l.y * viewP[p1] + l.z * viewP[p2];
    float sh = l.x * scalar[p0] + l.y * scalar[p1] + l.z * scalar[p2];
    setThick(viewP[p3], scalar[p3], h, sh);
  }
  else if (cls == 2)
  {
    // Crossing of projected edges p0p1 and p2p3 (seed 003 Fig. 4, class 2).
    vec2 d1 = ndc[p1] - ndc[p0], d2 = ndc[p3] - ndc[p2];
    float den = cross2(d1, d2);
    float t = cross2(ndc[p2] - ndc[p0], d2) / den;
    float u = cross2(ndc[p2] - ndc[p0], d1) / den;
    vec3 pa, pb;
    float sa, sb;
    alongEdge(p0, p1, clamp(t, 0.0, 1.0), pa, sa);
    alongEdge(p2, p3, clamp(u, 0.0, 1.0), pb, sb);
    setThick(pa, sa, pb, sb);
  }
  else if (cls == 3)
  {
    vec3 h;
    float sh;
    alongEdge(p0, p1, edgeParam(p0, p1, p3), h, sh);
    setThick(viewP[p3], scalar[p3], h, sh);
  }
  else if (cls == 4)
  {
    setThick(viewP[p2], scalar[p2], viewP[p3], scalar[p3]);
  }
}

// Emits the Shirley-Tuchman decomposition of the classified projection.
void emitProjection()
{
  if (cls == 1)
  {
    emitThin(p0); emitThin(p1); setEdge(p0, p1); emitThick();
    setEdge(p1, p2); emitThin(p2); setEdge(p2, p0); emitThin(p0);
    EndPrimitive();
  }
  else if (cls == 2)
  {
    // silhouette quad p0 p2 p1 p3 around the crossing
    emitThin(p0); emitThin(p2); setEdge(p0, p2); emitThick();
    setEdge(p2, p1); emitThin(p1); setEdge(p1, p3); emitThin(p3);
    EndPrimitive();
    emitThin(p3); emitThin(p0); setEdge(p3, p0); emitThick();
    EndPrimitive();
  }
  else if (cls == 3)
  {
    emitThin(p1); emitThin(p2); setEdge(p1, p2); emitThick();
    setEdge(p2, p0); emitThin(p0);
    EndPrimitive();
  }
  else if (cls == 4)
  {
    emitThin(p0); emitThin(p1); setEdge(p0, p1); emitThick();
    EndPrimitive();
  }
}

// The cell's volume: projected, or as a screen box when the near plane cuts it.
void emitVolume(bool nearClipped)
{
#ifdef PSI_NEAR_CLIP
  if (nearClipped)
  {
    emitClipped();
    return;
  }
#endif
  emitProjection();
}

#ifdef PSI_ISO_TRIANGLES
// One vertex of an isosurface polygon: where isovalue c crosses edge a-b.
void emitIsoVertex(int a, int b, float c)
{
  float t = clamp((c - scalar[a]) / (scalar[b] - scalar[a]), 0.0, 1.0);
  vec3 p = mix(viewP[a], viewP[b], t);
  vec3 n = mix(pointNormal[a], pointNormal[b], t);
  setFlat(0);
#ifdef PSI_EXACT_SEGMENTS
  frontPoint = vec4(n, 0.0);
#else
  segment = n;
#endif
  gl_Position = VCDCMatrix * vec4(p, 1.0);
  EmitVertex();
}

// Marching tetrahedra for isovalue i: a vertex is above when s >= c, so a surface exactly on a
// face shared by two cells belongs to one of them only. One vertex apart: a triangle on its three
// edges; two and two: a quad, as a strip of two triangles.
void emitSurface(int i)
{
  float c = isoValues[i];
  currentPiece = -float(i + 1);
  // GLSL 1.50: no bitCount / findLSB; vertices listed above first, then below.
  int order[4];
  int count = 0;
  for (int k = 0; k < 4; ++k)
  {
    if (scalar[k] >= c)
    {
      order[count++] = k;
    }
  }
  int n = count;
  for (int k = 0; k < 4; ++k)
  {
    if (scalar[k] < c)
    {
      order[n++] = k;
    }
  }
  if (count == 0 || count == 4)
  {
    return;
  }
  if (count == 2)
  {
    emitIsoVertex(order[0], order[2], c); emitIsoVertex(order[0], order[3], c);
    emitIsoVertex(order[1], order[2], c); emitIsoVertex(order[1], order[3], c);
  }
  else
  {
    int lone = count == 1 ? order[0] : order[3];
    for (int k = 0; k < 4; ++k)
    {
      if (k != lone)
      {
        emitIsoVertex(lone, k, c);
      }
    }
  }
  EndPrimitive();
}

// Draws piece j of the cell's volume (skipped when early discard finds it transparent).
void emitPiece(int j, float smin, float smax, bool nearClipped)
{
#ifdef PSI_EARLY_DISCARD
  float lo = j > 0 && j <= PSI_ISO_COUNT ? max(isoValues[j - 1], smin) : smin;
  float hi = j < PSI_ISO_COUNT ? min(isoValues[j], smax) : smax;
  if (transparentRange(lo, hi))
  {
    return;
  }
#endif
  currentPiece = float(j);
  emitVolume(nearClipped);
}

// Along a ray from the eye the (linear) scalar is monotone, starting from its extrapolated value
// at the eye, sEye: the level sets crossed are the ones on one side of sEye, nearest first. So,
// back to front: the pieces above sEye from the highest down, each followed by the surface at
// its lower end; the pieces below sEye from the lowest up, each followed by the surface at its
// upper end (no ray sees both sides); last the piece containing sEye. In parallel projection
// sEye is -inf or +inf, by the sign of the scalar's change along the view direction (0, 0, -1).
void emitPiecesAndSurfaces(float smin, float smax, bool nearClipped)
{
  const float big = 3.0e38;
  int first = 0;
  while (first < PSI_ISO_COUNT && isoValues[first] <= smin)
  {
    ++first;
  }
  int last = first - 1;
  while (last + 1 < PSI_ISO_COUNT && isoValues[last + 1] <= smax)
  {
    ++last;
  }
  if (last < first)
  {
    emitPiece(PSI_ISO_COUNT + 1, smin, smax, nearClipped); // no crossing: the whole cell
    return;
  }
  fetchNormals(); // only cells with a surface pay for the normals
  float sEye = parallelProjection == 1 ? (gradient.z < 0.0 ? -big : big)
                                       : scalar[0] - dot(gradient, viewP[0]);
  // piece j lies between isoValues[j - 1] and isoValues[j]; this cell has pieces first..last+1
  int e = first;
  while (e <= last && isoValues[e] <= sEye)
  {
    ++e;
  }
  for (int j = last + 1; j > e; --j)
  {
    emitPiece(j, smin, smax, nearClipped);
    emitSurface(j - 1);
  }
  for (int j = first; j < e; ++j)
  {
    emitPiece(j, smin, smax, nearClipped);
    emitSurface(j);
  }
  emitPiece(e, smin, smax, nearClipped);
}
#endif

void main()
{
  vec4 raw[4] = vec4[4](vsP0[0], vsP1[0], vsP2[0], vsP3[0]);
  float smin = min(min(raw[0].w, raw[1].w), min(raw[2].w, raw[3].w));
  float smax = max(max(raw[0].w, raw[1].w), max(raw[2].w, raw[3].w));
#if defined(PSI_EARLY_DISCARD) && !defined(PSI_ISO_TRIANGLES)
  if (transparentRange(smin, smax))
  {
    return;
  }
#endif
  int inFront = 0;
  for (int i = 0; i < 4; ++i)
  {
    viewP[i] = raw[i].xyz;
    scalar[i] = raw[i].w;
#ifdef PSI_NEAR_CLIP
    inFront += viewP[i].z > nearZ ? 1 : 0;
#endif
  }
#if defined(PSI_EXACT_SEGMENTS) || defined(PSI_ISO_COUNT)
  {
    // s(x) = s0 + g . (x - V0) with g from the three edge equations (Cramer's rule).
    vec3 e1 = viewP[1] - viewP[0], e2 = viewP[2] - viewP[0], e3 = viewP[3] - viewP[0];
    vec3 c23 = cross(e2, e3), c31 = cross(e3, e1), c12 = cross(e1, e2);
    float det = dot(e1, c23);
    float scale = max(max(dot(e1, e1), dot(e2, e2)), dot(e3, e3));
    bool degenerate = abs(det) <= 1e-7 * scale * sqrt(scale);
#if defined(PSI_EXACT_SEGMENTS) || defined(PSI_ISO_TRIANGLES)
    if (degenerate)
    {
      return; // a zero-volume tetrahedron has no interior to integrate or to cut a surface from
    }
#endif
    gradient = degenerate ? vec3(0.0)
                          : ((scalar[1] - scalar[0]) * c23 + (scalar[2] - scalar[0]) * c31 +
                              (scalar[3] - scalar[0]) * c12) / det;
  }
#endif
#ifdef PSI_ISO_PER_FRAGMENT
  fetchNormals();
#endif
#ifdef PSI_ISO_PER_FRAGMENT
  {
    mat3 E = mat3(viewP[1] - viewP[0], viewP[2] - viewP[0], viewP[3] - viewP[0]);
    float det = determinant(E);
    float scale = max(max(dot(E[0], E[0]), dot(E[1], E[1])), dot(E[2], E[2]));
    tetIsoG0 = pointNormal[0];
    // J E = [n1-n0 n2-n0 n3-n0]; a degenerate cell keeps the vertex gradient (flat shading).
    tetIsoJ = abs(det) > 1e-7 * scale * sqrt(scale) ?
      mat3(pointNormal[1] - pointNormal[0], pointNormal[2] - pointNormal[0],
        pointNormal[3] - pointNormal[0]) * inverse(E) : mat3(0.0);
  }
#endif
  bool nearClipped = false;
#ifdef PSI_NEAR_CLIP
  if (inFront == 4)
  {
    return; // wholly between the eye and the near plane (or behind the eye)
  }
  nearClipped = inFront > 0;
#endif
  if (!nearClipped)
  {
    for (int i = 0; i < 4; ++i)
    {
      clipP[i] = VCDCMatrix * vec4(viewP[i], 1.0);
      if (clipP[i].w <= 0.0)
      {
        return; // behind the eye; only reachable without PSI_NEAR_CLIP, which the mapper prevents
      }
      ndc[i] = clipP[i].xy / clipP[i].w;
    }
    classify();
  }
#ifdef PSI_ISO_TRIANGLES
  emitPiecesAndSurfaces(smin, smax, nearClipped);
#else
  emitVolume(nearClipped);
#endif
}
