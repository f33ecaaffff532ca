//PSI::IsoTriangles::Dec
// On-the-fly marching tetrahedra (Maximo et al. 2010 §3.4): the scalar is linear in the
// tetrahedron, so each isosurface crossing the cell is the planar marching-tetrahedra polygon,
// emitted as one or two triangles, in visibility order with the volume: the cell is drawn once
// per scalar interval between its crossings ("piece"), the farthest first, each piece's
// fragments integrating only the part of their ray segment inside that interval, with the
// surface that bounds the piece on the eye's side drawn right after it (Röttger et al. 2000 §10:
// behind, surface, in front). Primitives emitted by one invocation are blended in emission
// order. Surface vertices carry their normal in the segment slot (setVertexNormal).
uniform float isoValues[PSI_ISO_COUNT]; // ascending
uniform bool nearestFirst; // the frame composites front to back (PsiFramePlan::FrontToBack)
// The flat output piece (declared by psi::GeometryOutputs, PsiStageInterface.cxx; one
// component, to fit more isovalues in the geometry shader's output): j >= 0, the volume between
// isoValues[j - 1] and isoValues[j] (j = 0 .. PSI_ISO_COUNT, open-ended at the ends),
// j = PSI_ISO_COUNT + 1 the whole cell; -(i + 1): the surface of isovalue i.
float currentPiece = float(PSI_ISO_COUNT + 1);

//PSI::IsoTriangles::Flat
  piece = currentPiece;

//PSI::IsoTriangles::Degenerate
    if (degenerate)
    {
      return; // a zero-volume tetrahedron has no interior to cut a surface from
    }

//PSI::IsoTriangles::Impl
// One vertex of an isosurface polygon: where isovalue c crosses edge a-b.
void emitIsoVertex(int a, int b, float c)
{
  float t = clamp((c - scalar[a]) / (scalar[b] - scalar[a]), 0.0, 1.0);
  vec3 p = mix(viewP[a], viewP[b], t);
  vec3 n = mix(pointNormal[a], pointNormal[b], t);
  setFlat(0);
  setVertexNormal(n);
  psiEmitVertex(VCDCMatrix * vec4(p, 1.0));
}

// Marching tetrahedra for isovalue i: a vertex is above when s >= c, so a surface exactly on a
// face shared by two cells belongs to one of them only. One vertex apart: a triangle on its three
// edges; two and two: a quad, as a strip of two triangles (at most 4 vertices).
void emitSurface(int i)
{
  float c = isoValues[i];
  currentPiece = -float(i + 1);
  // GLSL 1.50: no bitCount / findLSB; vertices listed above first, then below.
  int order[4];
  int count = 0;
  for (int k = 0; k < 4; ++k)
  {
    if (scalar[k] >= c)
    {
      order[count++] = k;
    }
  }
  int n = count;
  for (int k = 0; k < 4; ++k)
  {
    if (scalar[k] < c)
    {
      order[n++] = k;
    }
  }
  if (count == 0 || count == 4)
  {
    return;
  }
  if (count == 2)
  {
    emitIsoVertex(order[0], order[2], c); emitIsoVertex(order[0], order[3], c);
    emitIsoVertex(order[1], order[2], c); emitIsoVertex(order[1], order[3], c);
  }
  else
  {
    int lone = count == 1 ? order[0] : order[3];
    for (int k = 0; k < 4; ++k)
    {
      if (k != lone)
      {
        emitIsoVertex(lone, k, c);
      }
    }
  }
  psiEndPrimitive();
}

// Draws piece j of the cell's volume (skipped when early discard finds it transparent).
void emitPiece(int j, float smin, float smax, bool nearClipped)
{
//PSI::EarlyDiscard::Piece
  currentPiece = float(j);
  emitVolume(nearClipped);
}

// Along a ray from the eye the (linear) scalar is monotone, starting from its extrapolated value
// at the eye, sEye: the level sets crossed are the ones on one side of sEye, nearest first. So,
// back to front: the pieces above sEye from the highest down, each followed by the surface at
// its lower end; the pieces below sEye from the lowest up, each followed by the surface at its
// upper end (no ray sees both sides); last the piece containing sEye. In parallel projection
// sEye is -inf or +inf, by the sign of the scalar's change along the view direction (0, 0, -1).
// Front to back (nearestFirst) the same sequence is emitted in reverse.
// At most PSI_ISO_COUNT + 1 pieces of 8 vertices and PSI_ISO_COUNT surfaces of 4.
//
// The sequence is one loop over its steps k (back to front: even k a piece, odd k the surface
// after it; the nAbove pieces above sEye, then the nBelow below it, then piece e), with one call
// of emitPiece and one of emitSurface: a shader compiler inlines every call, and a loop for each
// part and direction inlined the projection of a piece seven times (with llvmpipe the isosurface
// test's compute-projector run, camera inside, compiled for 169 s of CPU; 30.5 s as one loop).
void emitPiecesAndSurfaces(float smin, float smax, bool nearClipped)
{
  const float big = 3.0e38;
  int first = 0;
  while (first < PSI_ISO_COUNT && isoValues[first] <= smin)
  {
    ++first;
  }
  int last = first - 1;
  while (last + 1 < PSI_ISO_COUNT && isoValues[last + 1] <= smax)
  {
    ++last;
  }
  // piece j lies between isoValues[j - 1] and isoValues[j]; this cell has pieces first..last+1
  int e = PSI_ISO_COUNT + 1; // no crossing: the whole cell, one piece
  int nAbove = 0, nBelow = 0;
  if (last >= first)
  {
    fetchNormals(); // only cells with a surface pay for the normals
    float sEye = parallelProjection == 1 ? (gradient.z < 0.0 ? -big : big)
                                         : scalar[0] - dot(gradient, viewP[0]);
    e = first;
    while (e <= last && isoValues[e] <= sEye)
    {
      ++e;
    }
    nAbove = last + 1 - e;
    nBelow = e - first;
  }
  int steps = 2 * (nAbove + nBelow) + 1;
  for (int i = 0; i < steps; ++i)
  {
    int k = nearestFirst ? steps - 1 - i : i; // the step's place back to front
    int below = k - 2 * nAbove; // >= 0 among the pieces below sEye and their surfaces
    int j = k == steps - 1 ? e : below < 0 ? last + 1 - k / 2 : first + below / 2;
    if (k % 2 == 1)
    {
      emitSurface(below < 0 ? j - 1 : j); // the piece's lower end above sEye, upper end below
    }
    else
    {
      emitPiece(j, smin, smax, nearClipped);
    }
  }
}

//PSI::IsoTriangles::Emit
  emitPiecesAndSurfaces(smin, smax, nearClipped);
  return;
