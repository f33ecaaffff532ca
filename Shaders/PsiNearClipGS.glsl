//PSI::NearClip::Dec
// Near-plane clipping: tetrahedra that cross the near plane cannot be projected. They are drawn
// as a screen quad covering their near-clipped projection, and the fragment shader intersects
// each ray with the tetrahedron exactly (PsiNearClipFS.glsl). clipTet: the point ids (fetched by
// the fragment shader), x = -1 when not clipped; one output slot instead of four vertices keeps
// the geometry-shader output small (declared by psi::GeometryOutputs, PsiStageInterface.cxx).
uniform float nearZ; // view-space z of the near plane (negative)

//PSI::NearClip::Flat
  clipTet = isClipped == 1 ? ivec4(tetIn[0].ids) : ivec4(-1);

//PSI::NearClip::Impl
// Extends the screen box lo..hi by the projection of view-space point p (in front of the eye).
void includePoint(vec3 p, inout vec2 lo, inout vec2 hi)
{
  vec4 c = VCDCMatrix * vec4(p, 1.0);
  vec2 q = c.xy / c.w;
  lo = min(lo, q);
  hi = max(hi, q);
}

// Emits the screen box of the part of the tetrahedron beyond the near plane.
void emitClipped()
{
  vec2 lo = vec2(1e30), hi = vec2(-1e30);
  for (int i = 0; i < 4; ++i)
  {
    if (viewP[i].z <= nearZ)
    {
      includePoint(viewP[i], lo, hi);
    }
    for (int j = i + 1; j < 4; ++j)
    {
      float di = viewP[i].z - nearZ, dj = viewP[j].z - nearZ;
      if (di * dj < 0.0)
      {
        includePoint(mix(viewP[i], viewP[j], di / (di - dj)), lo, hi);
      }
    }
  }
  lo = max(lo, vec2(-1.0));
  hi = min(hi, vec2(1.0));
  if (lo.x > hi.x || lo.y > hi.y)
  {
    return;
  }
  vec2 corner[4] = vec2[4](lo, vec2(hi.x, lo.y), vec2(lo.x, hi.y), hi);
  for (int k = 0; k < 4; ++k)
  {
    setFlat(1);
    setVertexSegment(vec3(0.0), vec3(0.0));
    psiEmitVertex(vec4(corner[k], -1.0, 1.0)); // on the near plane: passes the depth test
  }
  psiEndPrimitive();
}

//PSI::NearClip::Volume
  if (nearClipped)
  {
    emitClipped();
    return;
  }

//PSI::NearClip::Count
    inFront += viewP[i].z > nearZ ? 1 : 0;

//PSI::NearClip::Cull
  if (inFront == 4)
  {
    return; // wholly between the eye and the near plane (or behind the eye)
  }
  nearClipped = inFront > 0;
