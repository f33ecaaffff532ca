//PSI::ProjectionClasses::Dec
// Projection classes of PTINT (Marroquim et al. 2008, Fig. 3): the four orientation tests index
// the 81-entry ternary truth table, derived and tested on the CPU (PsiProjectionClasses.cxx) and
// passed as `classTable`: entry = class | p0<<4 | p1<<6 | p2<<8 | p3<<10.
//   class 1: p3 inside triangle p0 p1 p2          -> fan of 3 around p3      (thick vertex p3)
//   class 2: segment p0p1 crosses segment p2p3    -> fan of 4 around the crossing
//   class 3: p3 on segment p0p1                    -> fan of 2 around p3
//   class 4: p2 and p3 project to the same point   -> 1 triangle, thick vertex p2/p3
// The largest decomposition (class 2: a strip of 5 and one of 3) has 8 vertices.
uniform int classTable[81];

// Projection class and the four vertices in the class's order, from the truth table.
int cls = 0, p0 = 0, p1 = 0, p2 = 0, p3 = 0;

//PSI::ProjectionClasses::Impl
// Marroquim et al. 2008, Fig. 3: classifies the projection and computes the thick vertex's
// segment.
void classify()
{
  int t1 = int(sign(cross2(ndc[1] - ndc[0], ndc[2] - ndc[0]))) + 1;
  int t2 = int(sign(cross2(ndc[1] - ndc[0], ndc[3] - ndc[0]))) + 1;
  int t3 = int(sign(cross2(ndc[2] - ndc[0], ndc[3] - ndc[0]))) + 1;
  int t4 = int(sign(cross2(ndc[1] - ndc[2], ndc[1] - ndc[3]))) + 1;
  int entry = classTable[27 * t1 + 9 * t2 + 3 * t3 + t4];
  cls = entry & 15;
  p0 = (entry >> 4) & 3;
  p1 = (entry >> 6) & 3;
  p2 = (entry >> 8) & 3;
  p3 = (entry >> 10) & 3;
  if (cls == 1)
  {
    // Ray through p3 meets face p0 p1 p2: screen barycentrics, made perspective-correct.
    vec2 a = ndc[p0], b = ndc[p1], c = ndc[p2], m = ndc[p3];
    float area = cross2(b - a, c - a);
    vec3 l = vec3(cross2(b - m, c - m), cross2(c - m, a - m), cross2(a - m, b - m)) / area;
    l /= vec3(clipP[p0].w, clipP[p1].w, clipP[p2].w);
    l /= (l.x + l.y + l.z);
    vec3 h = l.x * viewP[p0] + l.y * viewP[p1] + l.z * viewP[p2];
    float sh = l.x * scalar[p0] + l.y * scalar[p1] + l.z * scalar[p2];
    setThick(viewP[p3], scalar[p3], h, sh);
  }
  else if (cls == 2)
  {
    // Crossing of projected edges p0p1 and p2p3 (Marroquim et al. 2008, Fig. 4, class 2).
    vec2 d1 = ndc[p1] - ndc[p0], d2 = ndc[p3] - ndc[p2];
    float den = cross2(d1, d2);
    float t = cross2(ndc[p2] - ndc[p0], d2) / den;
    float u = cross2(ndc[p2] - ndc[p0], d1) / den;
    vec3 pa, pb;
    float sa, sb;
    alongEdge(p0, p1, clamp(t, 0.0, 1.0), pa, sa);
    alongEdge(p2, p3, clamp(u, 0.0, 1.0), pb, sb);
    setThick(pa, sa, pb, sb);
  }
  else if (cls == 3)
  {
    vec3 h;
    float sh;
    alongEdge(p0, p1, edgeParam(p0, p1, p3), h, sh);
    setThick(viewP[p3], scalar[p3], h, sh);
  }
  else if (cls == 4)
  {
    setThick(viewP[p2], scalar[p2], viewP[p3], scalar[p3]);
  }
}

// Emits the Shirley-Tuchman decomposition of the classified projection (HAPT's fan).
void emitFan()
{
  if (cls == 1)
  {
    emitThin(p0); emitThin(p1); setEdge(p0, p1); emitThick();
    setEdge(p1, p2); emitThin(p2); setEdge(p2, p0); emitThin(p0);
    psiEndPrimitive();
  }
  else if (cls == 2)
  {
    // silhouette quad p0 p2 p1 p3 around the crossing
    emitThin(p0); emitThin(p2); setEdge(p0, p2); emitThick();
    setEdge(p2, p1); emitThin(p1); setEdge(p1, p3); emitThin(p3);
    psiEndPrimitive();
    emitThin(p3); emitThin(p0); setEdge(p3, p0); emitThick();
    psiEndPrimitive();
  }
  else if (cls == 3)
  {
    emitThin(p1); emitThin(p2); setEdge(p1, p2); emitThick();
    setEdge(p2, p0); emitThin(p0);
    psiEndPrimitive();
  }
  else if (cls == 4)
  {
    emitThin(p0); emitThin(p1); setEdge(p0, p1); emitThick();
    psiEndPrimitive();
  }
}

// The silhouette of the classified projection, the convex hull of the four projected vertices:
// class 1 (p3 inside), 3 (p3 on edge p0p1) and 4 (p2 and p3 coincide) are the triangle p0 p1 p2;
// class 2 is the quad p0 p2 p1 p3, drawn as one covering triangle when that adds little area
// (psi::PsiSilhouetteCoverPixels), else as a strip of 4. Every fragment finds its own segment
// (PsiRaySegments*.glsl), empty outside the tetrahedron.
uniform float coverExtraMax; // NDC area a covering triangle may add to a quad silhouette

// A vertex of the silhouette's covering triangle at NDC point q, at the silhouette's depth.
void emitCover(vec2 q, float z)
{
  setFlat(0);
  setVertexSegment(viewP[p0], vec3(scalar[p0], scalar[p0], 0.0));
  psiEmitVertex(vec4(q, z, 1.0));
}

// Covers the convex quad q0 q1 q2 q3 (boundary order) with one triangle when that adds at most
// coverExtraMax of area: apex q_i and its edges to q_(i+1), q_(i-1) stretched by
// s = alpha + beta, where q_(i+2) - q_i = alpha (q_(i+1) - q_i) + beta (q_(i-1) - q_i); the
// triangle's area is s times the quad's, so the apex with the least s is taken.
bool emitQuadCover(vec2 q[4], float z)
{
  float best = 1e30;
  int apex = 0;
  for (int i = 0; i < 4; ++i)
  {
    vec2 e1 = q[(i + 1) % 4] - q[i], e2 = q[(i + 3) % 4] - q[i], d = q[(i + 2) % 4] - q[i];
    float det = cross2(e1, e2);
    float s = (cross2(d, e2) + cross2(e1, d)) / det;
    if (abs(det) > 0.0 && s >= 1.0 && s < best)
    {
      best = s;
      apex = i;
    }
  }
  vec2 e1 = q[(apex + 1) % 4] - q[apex], e2 = q[(apex + 3) % 4] - q[apex];
  float quadArea = 0.5 * best * abs(cross2(e1, e2));
  if (!(best < 4.0 && (best - 1.0) * quadArea <= coverExtraMax))
  {
    return false;
  }
  emitCover(q[apex], z);
  emitCover(q[apex] + best * e1, z);
  emitCover(q[apex] + best * e2, z);
  return true;
}

void emitSilhouette()
{
  if (cls == 2)
  {
    vec2 q[4] = vec2[4](ndc[p0], ndc[p2], ndc[p1], ndc[p3]);
    if (!emitQuadCover(q, clipP[p0].z / clipP[p0].w))
    {
      emitThin(p0); emitThin(p2); emitThin(p3); emitThin(p1); // the strip of quad p0 p2 p1 p3
    }
  }
  else
  {
    emitThin(p0); emitThin(p1); emitThin(p2);
  }
  psiEndPrimitive();
}
