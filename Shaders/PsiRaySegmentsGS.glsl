//PSI::RaySegments::Dec
// Ray segments (the silhouette decomposition): the projection is drawn as its silhouette (the
// convex hull of the four projected vertices, 1 or 2 triangles) instead of the 1-4 triangles of
// Shirley and Tuchman's fan, and each fragment intersects its own ray with the tetrahedron's
// four face planes (PsiRaySegmentsFS.glsl), exact in parallel and in perspective projection.
//
// The fragments need the four outward face planes n . x = w and the linear scalar
// s(x) = g . x + s0 of the cell, the same for the whole silhouette: flat outputs. (Interpolating
// the rays' plane parameters, which are affine in screen space, would be cheaper per fragment,
// but the rasterizer's clipping of large triangles near the eye does not keep them exact.)
flat out vec4 facePlane0; // n . x = w, outward, view coordinates
flat out vec4 facePlane1;
flat out vec4 facePlane2;
flat out vec4 facePlane3;
flat out vec4 scalarPlane; // g, s0: s(x) = g . x + s0
smooth out vec3 isoNormal;  // marching-tetrahedra surface vertices only

vec4 facePlanes[4];

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
  facePlane0 = facePlanes[0];
  facePlane1 = facePlanes[1];
  facePlane2 = facePlanes[2];
  facePlane3 = facePlanes[3];
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
  for (int i = 0; i < 4; ++i)
  {
    facePlanes[i] = outwardPlane(i);
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
