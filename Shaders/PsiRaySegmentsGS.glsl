//PSI::RaySegments::Dec
// Ray segments (the silhouette decomposition): the projection is drawn as its silhouette (the
// convex hull of the four projected vertices, 1 or 2 triangles) instead of the 1-4 triangles of
// Shirley and Tuchman's fan, and each fragment intersects its own ray with the tetrahedron's
// four face planes (PsiRaySegmentsFS.glsl), exact in parallel and in perspective projection.
//
// The ray of the pixel at window position (x, y) is X(t) = O + t S with O and S affine in (x, y)
// (psi::PixelRaysOf, PsiPixelRays.h): in perspective O is the eye (constant) and S varies, in
// parallel projection S is constant and O varies. It meets the outward face plane n . X = w at
//   t = (w - n . O) / (n . S),
// a constant over an affine function of (x, y) in perspective, the reverse in parallel
// projection. Whether the ray enters or leaves through a face does not depend on the pixel: in
// perspective every ray starts at the eye, so it enters through the faces whose planes have the
// eye outside (w - n . O < 0); in parallel projection every ray has the direction S, so it
// enters where n . S < 0. The geometry shader therefore passes, per face, that flag and an
// affine function p = p0 + x px + y py whose extremes give the segment with one division each:
//   parallel:    p = t (affine),       t_enter = max p over entering faces, t_exit = min p over
//                                      leaving ones;
//   perspective: p = -1/t = -(n . S) / (w - n . O) (affine), and as -1/t grows with t, the same
//                max and min give t_enter = -1 / max p, t_exit = -1 / min p.
// A face parallel to the rays (n . S = 0 in parallel projection; the eye on its plane in
// perspective) bounds nothing and gets p = -BIG among the entering faces. Along the ray the linear
// scalar s = g . X + s0 is s(t) = a + t b with a = g . O + s0 and b = g . S, one constant and
// the other affine in (x, y): four terms. Four faces to a vec4; all flat outputs.
// (Interpolating such terms as varyings would save the fragment shader a few multiply-adds, but
// the rasterizer's clipping of large triangles near the eye does not keep them exact, and on
// llvmpipe the interpolated inputs' setup costs what the flat ones save.)
// The outputs (flat rayFace0, rayFaceX, rayFaceY, scalarRay; smooth isoNormal) are declared by
// psi::GeometryOutputs (PsiStageInterface.cxx).

uniform vec3 pixelRayOrigin[3]; // O = [0] + x [1] + y [2]
uniform vec3 pixelRayStep[3];   // S likewise

vec4 faceP0 = vec4(0.0), facePX = vec4(0.0), facePY = vec4(0.0), scalarTerms = vec4(0.0);

// Whether the ray enters through each face rides in the lowest mantissa bit of the face's p0
// instead of an output of its own: the rasterizer's setup and the fragment's interpolation cost
// per output (docs/decisions.md, "Silhouettes": enter flags). The bit moves p0 by at
// most one unit in the last place, less than the rounding of p0 itself; a flat output reaches
// the fragment shader bit for bit.
vec4 withEnterFlags(vec4 p0, bvec4 enters)
{
  return uintBitsToFloat((floatBitsToUint(p0) & ~1u) | uvec4(enters));
}

vec4 outwardPlane(int i)
{
  vec3 a = viewP[(i + 1) % 4], b = viewP[(i + 2) % 4], c = viewP[(i + 3) % 4];
  vec3 n = cross(b - a, c - a);
  n = dot(n, viewP[i] - a) > 0.0 ? -n : n;
  return vec4(n, dot(n, a));
}

// Every vertex carries the cell's ray terms (the provoking vertex's are used).
void setVertexSegment(vec3 p, vec3 seg)
{
  rayFace0 = faceP0;
  rayFaceX = facePX;
  rayFaceY = facePY;
  scalarRay = scalarTerms;
//PSI::SeparateOpacity::Vertex
}

// A marching-tetrahedra surface vertex carries its normal (interpolated across the surface).
void setVertexNormal(vec3 n)
{
  isoNormal = n;
}

// The fan's per-triangle data: none here.
void setEdge(int a, int b)
{
}

//PSI::RaySegments::Emit
// The terms of the four faces' p = p0 + x px + y py and of the scalar along the ray (above).
void setRayTerms()
{
  mat4 planes = mat4(outwardPlane(0), outwardPlane(1), outwardPlane(2), outwardPlane(3));
  vec4 w = vec4(planes[0].w, planes[1].w, planes[2].w, planes[3].w);
  // vec4(v, 0) * planes = (n_i . v) for the four faces; t = num / den per face.
  vec4 num0 = w - vec4(pixelRayOrigin[0], 0.0) * planes;
  vec4 numX = -(vec4(pixelRayOrigin[1], 0.0) * planes);
  vec4 numY = -(vec4(pixelRayOrigin[2], 0.0) * planes);
  vec4 den0 = vec4(pixelRayStep[0], 0.0) * planes;
  vec4 denX = vec4(pixelRayStep[1], 0.0) * planes;
  vec4 denY = vec4(pixelRayStep[2], 0.0) * planes;
  bool parallel = parallelProjection == 1;
  vec4 constant = parallel ? den0 : num0; // the term that does not depend on (x, y)
  bvec4 bounds = notEqual(constant, vec4(0.0));
  vec4 scale = mix(vec4(0.0), (parallel ? 1.0 : -1.0) / constant, bounds);
  bvec4 enters = bvec4(mix(vec4(1.0), vec4(lessThan(constant, vec4(0.0))), bounds));
  faceP0 = withEnterFlags(mix(vec4(-3.0e38), (parallel ? num0 : den0) * scale, bounds), enters);
  facePX = (parallel ? numX : denX) * scale;
  facePY = (parallel ? numY : denY) * scale;
  float s0 = scalar[0] - dot(gradient, viewP[0]);
  // O varies in parallel projection, S in perspective (psi::PixelRaysOf)
  vec3 movingX = parallel ? pixelRayOrigin[1] : pixelRayStep[1];
  vec3 movingY = parallel ? pixelRayOrigin[2] : pixelRayStep[2];
  scalarTerms = vec4(dot(gradient, pixelRayOrigin[0]) + s0, dot(gradient, pixelRayStep[0]),
    dot(gradient, movingX), dot(gradient, movingY));
}

// The silhouette, at the depth of the tetrahedron's nearest vertex: the hardware depth test
// against opaque geometry then never rejects a fragment whose segment starts in front of it;
// the fragment shader tests the segment's own front depth.
void emitProjection()
{
  setRayTerms();
  float nearest = min(min(clipP[0].z / clipP[0].w, clipP[1].z / clipP[1].w),
    min(clipP[2].z / clipP[2].w, clipP[3].z / clipP[3].w));
  for (int i = 0; i < 4; ++i)
  {
    clipP[i].z = nearest * clipP[i].w;
  }
  emitSilhouette();
}

//PSI::RaySegments::Degenerate
    if (degenerate)
    {
      return; // a zero-volume tetrahedron has no interior to integrate
    }
