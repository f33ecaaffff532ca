//PSI::RaySegments::Dec
// Ray segments (PsiRaySegmentsGS.glsl): the ray of this pixel is X(t) = O + t S, O and S affine
// in the window position (psi::PixelRaysOf; for VTK's cameras S.z = -1 and t is the view
// depth). It meets face i at t_i = K_i / L_i in perspective and L_i / K_i in parallel
// projection, L = L0 + x Lx + y Ly. It enters the tetrahedron at the largest t of the planes it
// crosses inwards (n . S < 0) and leaves at the smallest t of those it crosses outwards
// (n . S > 0); a plane parallel to the ray bounds nothing, as the pixel lies inside the
// silhouette. Along the ray the scalar is s(t) = (g . O + s0) + t (g . S).
flat in vec4 rayPlaneK;
flat in vec4 rayPlane0;
flat in vec4 rayPlaneX;
flat in vec4 rayPlaneY;
flat in vec4 scalarPlane; // g, s0
smooth in vec3 isoNormal;

uniform vec3 pixelRayOrigin[3]; // O = [0] + x [1] + y [2]
uniform vec3 pixelRayStep[3];   // S likewise

vec3 rayOrigin, rayStep; // O and S of this pixel's ray
float rayEntry;          // t where the ray enters the tetrahedron

void readSegment(out float sf, out float sb, out float D)
{
  vec2 x = gl_FragCoord.xy;
  rayOrigin = pixelRayOrigin[0] + x.x * pixelRayOrigin[1] + x.y * pixelRayOrigin[2];
  rayStep = pixelRayStep[0] + x.x * pixelRayStep[1] + x.y * pixelRayStep[2];
  vec4 L = rayPlane0 + x.x * rayPlaneX + x.y * rayPlaneY;
  bool parallel = parallelProjection == 1;
  vec4 den = parallel ? rayPlaneK : L; // n . S
  vec4 t = (parallel ? L : rayPlaneK) / den;
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
