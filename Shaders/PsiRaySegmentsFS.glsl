//PSI::RaySegments::Dec
// Ray segments (PsiRaySegmentsGS.glsl): the ray of this pixel is X(t) = O + t S, O and S affine
// in the window position (psi::PixelRaysOf; for VTK's cameras S.z = -1 and t is the view
// depth). Per face the geometry shader passes whether the ray enters or leaves through it and an
// affine function p of the window position: p = t in parallel projection, p = -1/t in
// perspective, both growing with t. The ray enters at the largest p of the faces it enters
// through and leaves at the smallest p of those it leaves through. Along the ray the scalar is
// s(t) = a + t b: a is affine in the window position and b constant in parallel projection,
// the reverse in perspective.
flat in vec4 rayFace0; // lowest bit: the ray enters through the face (PsiRaySegmentsGS.glsl)
flat in vec4 rayFaceX;
flat in vec4 rayFaceY;
flat in vec4 scalarRay; // a0, b0, c_x, c_y (PsiRaySegmentsGS.glsl)
smooth in vec3 isoNormal;

uniform vec3 pixelRayOrigin[3]; // O = [0] + x [1] + y [2]
uniform vec3 pixelRayStep[3];   // S likewise

vec3 rayOrigin = vec3(0.0), rayStep = vec3(0.0); // O and S of this pixel's ray
float rayEntry = 0.0; // t where the ray enters the tetrahedron

void readSegment(out float sf, out float sb, out float D)
{
  vec2 x = gl_FragCoord.xy;
  rayOrigin = pixelRayOrigin[0] + x.x * pixelRayOrigin[1] + x.y * pixelRayOrigin[2];
  rayStep = pixelRayStep[0] + x.x * pixelRayStep[1] + x.y * pixelRayStep[2];
  vec4 p = rayFace0 + x.x * rayFaceX + x.y * rayFaceY;
  bvec4 enters = notEqual(floatBitsToUint(rayFace0) & 1u, uvec4(0u));
  vec4 pin = mix(vec4(-3.0e38), p, enters);
  vec4 pout = mix(p, vec4(3.0e38), enters);
  float a = max(max(pin.x, pin.y), max(pin.z, pin.w));
  float b = min(min(pout.x, pout.y), min(pout.z, pout.w));
  float k = float(parallelProjection), rayExit;
  if (parallelProjection == 1)
  {
    rayEntry = a;
    rayExit = max(b, a);
  }
  else
  {
    // p < 0 in front of the eye; p >= 0 only outside the silhouette, where D becomes 0.
    rayEntry = -1.0 / min(a, -1.0e-30);
    rayExit = max(-1.0 / b, rayEntry);
  }
  D = (rayExit - rayEntry) * length(rayStep);
  float u = x.x * scalarRay.z + x.y * scalarRay.w;
  float sa = scalarRay.x + k * u, sd = scalarRay.y + (1.0 - k) * u;
  sf = sa + rayEntry * sd;
  sb = sa + rayExit * sd;
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
