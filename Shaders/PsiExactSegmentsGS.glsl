//PSI::ExactSegments::Dec
// Exact segments in perspective: screen-linear interpolation of thickness is only approximate
// (it is exact in parallel projection, where the (s_f, s_b, l) triple of Maximo et al. 2010 §3.2
// is used). Every fan triangle lies in the tetrahedron's front face for its rays, so
// perspective-correct interpolation of the view-space front point and front scalar is exact; the
// rays leave through the other face sharing the triangle's thin edge a-b (the back plane), where
// one plane intersection per fragment gives the exact thickness and, with the scalar gradient,
// the back scalar.
// The outputs (smooth frontPoint; flat backPlane, scalarGrad) are declared by
// psi::GeometryOutputs (PsiStageInterface.cxx).

// The segment carried by the next vertex: its view-space point and front scalar.
void setVertexSegment(vec3 p, vec3 seg)
{
  frontPoint = vec4(p, seg.x);
}

// A marching-tetrahedra surface vertex carries its normal in frontPoint.xyz.
void setVertexNormal(vec3 n)
{
  frontPoint = vec4(n, 0.0);
}

vec4 facePlane(int a, int b, int c)
{
  vec3 n = cross(viewP[b] - viewP[a], viewP[c] - viewP[a]);
  return vec4(n, dot(n, viewP[a]));
}

float planeDistance(vec4 plane, vec3 p)
{
  return abs(dot(plane.xyz, p) - plane.w) * inversesqrt(max(dot(plane.xyz, plane.xyz), 1e-37));
}

// Flat data of the triangle completed by the next vertex (the provoking, last, vertex): of the
// two faces sharing its thin edge a-b, the one through the thick front point is the front face,
// the other the back face.
void setEdge(int a, int b)
{
  int c = 0;
  while (c == a || c == b)
  {
    ++c;
  }
  int d = 6 - a - b - c;
  vec4 fc = facePlane(a, b, c), fd = facePlane(a, b, d);
  backPlane = planeDistance(fc, thickFront) <= planeDistance(fd, thickFront) ? fd : fc;
  scalarGrad = vec4(gradient, 1.5 * thickSeg.z);
}

//PSI::ExactSegments::Degenerate
    if (degenerate)
    {
      return; // a zero-volume tetrahedron has no interior to integrate
    }

//PSI::ExactSegments::Emit
// The projection as Shirley and Tuchman's fan around the thick vertex (Maximo et al. 2010 §3.2).
void emitProjection()
{
  emitFan();
}
