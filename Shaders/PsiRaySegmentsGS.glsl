//PSI::RaySegments::Dec
// Ray segments (the silhouette decomposition): the projection is drawn as its silhouette (the
// convex hull of the four projected vertices, 1 or 2 triangles) instead of the 1-4 triangles of
// Shirley and Tuchman's fan, and each fragment intersects its own ray with the tetrahedron's
// four face planes (PsiRaySegmentsFS.glsl), exact in parallel and in perspective projection.
//
// The fragments need where their ray meets the four outward face planes n . x = w, and the
// linear scalar s(x) = g . x + s0 of the cell, the same for the whole silhouette: flat outputs.
// The ray of the pixel at window position (x, y) is X(t) = O + t S with O and S affine in (x, y)
// (psi::PixelRaysOf, PsiPixelRays.h): in perspective O is the eye (constant) and S varies, in
// parallel projection S is constant and O varies. A plane is met at
//   t = (w - n . O) / (n . S),
// a constant over an affine function of (x, y) in perspective, the reverse in parallel
// projection. Per plane the geometry shader passes the constant K and the affine function's
// three coefficients L = L0 + x Lx + y Ly, four planes to a vec4. (Interpolating the ratio's
// terms as varyings would save the fragment shader two multiply-adds, but the rasterizer's
// clipping of large triangles near the eye does not keep them exact.)
flat out vec4 rayPlaneK;  // the constant term of each face's t
flat out vec4 rayPlane0;  // L0, Lx, Ly: its affine term
flat out vec4 rayPlaneX;
flat out vec4 rayPlaneY;
flat out vec4 scalarPlane; // g, s0: s(x) = g . x + s0
smooth out vec3 isoNormal;  // marching-tetrahedra surface vertices only

uniform vec3 pixelRayOrigin[3]; // O = [0] + x [1] + y [2]
uniform vec3 pixelRayStep[3];   // S likewise

vec4 rayK, rayL0, rayLX, rayLY;

vec4 outwardPlane(int i)
{
  vec3 a = viewP[(i + 1) % 4], b = viewP[(i + 2) % 4], c = viewP[(i + 3) % 4];
  vec3 n = cross(b - a, c - a);
  n = dot(n, viewP[i] - a) > 0.0 ? -n : n;
  return vec4(n, dot(n, a));
}

// Every vertex carries the cell's planes (the provoking vertex's are used).
void setVertexSegment(vec3 p, vec3 seg)
{
  rayPlaneK = rayK;
  rayPlane0 = rayL0;
  rayPlaneX = rayLX;
  rayPlaneY = rayLY;
  scalarPlane = vec4(gradient, scalar[0] - dot(gradient, viewP[0]));
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
// The silhouette, at the depth of the tetrahedron's nearest vertex: the hardware depth test
// against opaque geometry then never rejects a fragment whose segment starts in front of it;
// the fragment shader tests the segment's own front depth.
void emitProjection()
{
  mat4 planes = mat4(outwardPlane(0), outwardPlane(1), outwardPlane(2), outwardPlane(3));
  vec4 w = vec4(planes[0].w, planes[1].w, planes[2].w, planes[3].w);
  // vec4(v, 0) * planes = (n_i . v) for the four faces.
  if (parallelProjection == 1)
  {
    rayK = vec4(pixelRayStep[0], 0.0) * planes;
    rayL0 = w - vec4(pixelRayOrigin[0], 0.0) * planes;
    rayLX = -(vec4(pixelRayOrigin[1], 0.0) * planes);
    rayLY = -(vec4(pixelRayOrigin[2], 0.0) * planes);
  }
  else
  {
    rayK = w - vec4(pixelRayOrigin[0], 0.0) * planes;
    rayL0 = vec4(pixelRayStep[0], 0.0) * planes;
    rayLX = vec4(pixelRayStep[1], 0.0) * planes;
    rayLY = vec4(pixelRayStep[2], 0.0) * planes;
  }
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
