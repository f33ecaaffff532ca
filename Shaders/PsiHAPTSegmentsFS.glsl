//PSI::HAPTSegments::Dec
// The ray segment as the (s_f, s_b, l) triple of Maximo et al. 2010 §3.2, interpolated linearly
// in screen space (exact in parallel projection).
noperspective in vec3 segment; // front scalar, back scalar, thickness

void readSegment(out float sf, out float sb, out float D)
{
  sf = segment.x;
  sb = segment.y;
  D = segment.z;
}

// The view-space front point of the segment and the unit ray direction.
void frontRay(out vec3 p, out vec3 dir)
{
  p = viewPointAt(gl_FragCoord.z);
  dir = parallelProjection == 1 ? vec3(0.0, 0.0, -1.0) : normalize(p);
}

// The normal a marching-tetrahedra surface vertex carries in the segment slot.
vec3 surfaceNormal()
{
  return segment;
}

// Window depth of the segment's front point: the fan triangle lies in the front face.
float segmentFrontDepth()
{
  return gl_FragCoord.z;
}
