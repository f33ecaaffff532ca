//PSI::ExactSegments::Dec
// Exact segments in perspective (PsiExactSegmentsGS.glsl): the ray from the eye through the
// (exactly interpolated) front point leaves through the back plane.
smooth in vec4 frontPoint;
flat in vec4 backPlane;
flat in vec4 scalarGrad;

void readSegment(out float sf, out float sb, out float D)
{
  vec3 dir = normalize(frontPoint.xyz);
  D = (backPlane.w - dot(backPlane.xyz, frontPoint.xyz)) / dot(backPlane.xyz, dir);
  D = clamp(D, 0.0, scalarGrad.w); // guards grazing rays at a silhouette edge
  sf = frontPoint.w;
  sb = sf + D * dot(scalarGrad.xyz, dir);
}

// The view-space front point of the segment and the unit ray direction.
void frontRay(out vec3 p, out vec3 dir)
{
  p = frontPoint.xyz;
  dir = normalize(frontPoint.xyz);
}

// The normal a marching-tetrahedra surface vertex carries in frontPoint.xyz.
vec3 surfaceNormal()
{
  return frontPoint.xyz;
}

// Window depth of the segment's front point: the fan triangle lies in the front face.
float segmentFrontDepth()
{
  return gl_FragCoord.z;
}
