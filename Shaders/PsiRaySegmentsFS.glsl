//PSI::RaySegments::Dec
// Ray segments (PsiRaySegmentsGS.glsl): the ray of this pixel, x(t) = E + t d with d.z = -1 (so
// t is the view depth -z; in perspective E = 0 and d = p / -p.z for the pixel's point p on the
// near plane, in parallel projection E = (p.x, p.y, 0) and d = (0, 0, -1)), meets each face
// plane n . x = w at t = (w - n . E) / (n . d). It enters the tetrahedron at the largest t of
// the planes it crosses inwards (n . d < 0) and leaves at the smallest t of those it crosses
// outwards (n . d > 0); a plane parallel to the ray bounds nothing, as the pixel lies inside
// the silhouette. Along the ray the scalar is s(t) = (g . E + s0) + t (g . d).
flat in vec4 facePlane0;
flat in vec4 facePlane1;
flat in vec4 facePlane2;
flat in vec4 facePlane3;
flat in vec4 scalarPlane; // g, s0
smooth in vec3 isoNormal;

vec3 rayOrigin, rayStep; // E and d of this pixel's ray
float rayEntry;          // t where the ray enters the tetrahedron

void readSegment(out float sf, out float sb, out float D)
{
  vec3 p = viewPointAt(0.0);
  bool parallel = parallelProjection == 1;
  rayStep = parallel ? vec3(0.0, 0.0, -1.0) : p / -p.z;
  rayOrigin = parallel ? vec3(p.xy, 0.0) : vec3(0.0);
  mat4 planes = mat4(facePlane0, facePlane1, facePlane2, facePlane3);
  vec4 num = vec4(facePlane0.w, facePlane1.w, facePlane2.w, facePlane3.w) -
    vec4(rayOrigin, 0.0) * planes;
  vec4 den = vec4(rayStep, 0.0) * planes;
  vec4 t = num / den;
  vec4 tin = mix(vec4(-3.0e38), t, lessThan(den, vec4(0.0)));
  vec4 tout = mix(vec4(3.0e38), t, greaterThan(den, vec4(0.0)));
  rayEntry = max(max(tin.x, tin.y), max(tin.z, tin.w));
  float rayExit = max(min(min(tout.x, tout.y), min(tout.z, tout.w)), rayEntry);
  D = (rayExit - rayEntry) * length(rayStep);
  float s0 = dot(scalarPlane.xyz, rayOrigin) + scalarPlane.w, ds = dot(scalarPlane.xyz, rayStep);
  sf = s0 + rayEntry * ds;
  sb = s0 + rayExit * ds;
//PSI::SeparateOpacity::Segment
}

// The view-space front point of the segment and the unit ray direction.
void frontRay(out vec3 p, out vec3 dir)
{
  p = rayOrigin + rayEntry * rayStep;
  dir = normalize(rayStep);
}

// Window depth of the segment's front point.
float segmentFrontDepth()
{
  vec4 c = VCDCMatrix * vec4(rayOrigin + rayEntry * rayStep, 1.0);
  return 0.5 * c.z / c.w + 0.5;
}

// The normal a marching-tetrahedra surface vertex carries.
vec3 surfaceNormal()
{
  return isoNormal;
}
