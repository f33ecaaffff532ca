//PSI::HAPTSegments::Dec
// The ray segment as HAPT's (s_f, s_b, l) triple (Maximo et al. 2010 §3.2), interpolated
// linearly in screen space: exact in parallel projection, approximate in perspective.
// The output (noperspective segment) is declared by psi::GeometryOutputs (PsiStageInterface.cxx).

// The segment carried by the next vertex: p is its view-space point (unused here).
void setVertexSegment(vec3 p, vec3 seg)
{
  segment = seg;
}

// A marching-tetrahedra surface vertex carries its normal in the segment slot.
void setVertexNormal(vec3 n)
{
  segment = n;
}

// The flat data of the next triangle: none for the screen-linear triple.
void setEdge(int a, int b)
{
}

//PSI::HAPTSegments::Emit
// The projection as Shirley and Tuchman's fan around the thick vertex (Maximo et al. 2010 §3.2).
void emitProjection()
{
  emitFan();
}
