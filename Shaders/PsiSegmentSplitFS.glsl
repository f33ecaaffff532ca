//PSI::SegmentSplit::Dec
// Segments split into pieces, integrated and composited front to back in this fragment: at
// transfer-function nodes (adaptive sampling, PsiAdaptiveFS.glsl) and at isovalue crossings
// (per-fragment isosurfaces, PsiIsoPerFragmentFS.glsl). PSI_MAX_SPLITS bounds the number of
// split points (isovalues plus transfer-function nodes).
vec4 splitAcc = vec4(0.0);
void addPiece(float sa, float sb, float D)
{
  if (D > 0.0)
  {
    splitAcc += (1.0 - splitAcc.a) * integrateSegment(sa, sb, D);
  }
}

// p0, dir: view-space front point and unit ray direction (isosurface shading only).
vec4 integrateSplit(float sf, float sb, float D, vec3 p0, vec3 dir)
{
  splitAcc = vec4(0.0);
  float ds = sb - sf;
  float dirS = ds >= 0.0 ? 1.0 : -1.0;
  float sPrev = sf, tPrev = 0.0;
//PSI::SeparateOpacity::SplitInit
//PSI::Adaptive::SplitInit
//PSI::IsoPerFragment::SplitInit
  for (int guard = 0; guard <= PSI_MAX_SPLITS; ++guard)
  {
    float next = sb;
    int kind = 0;
//PSI::Adaptive::SplitNext
//PSI::IsoPerFragment::SplitNext
    // kind != 0 implies ds != 0: no division by zero, no NaN
    float t = kind == 0 ? 1.0 : clamp((next - sf) / ds, tPrev, 1.0);
//PSI::SeparateOpacity::SplitPiece
    addPiece(sPrev, next, (t - tPrev) * D);
    if (kind == 0)
    {
      break;
    }
//PSI::Adaptive::SplitAdvance
//PSI::IsoPerFragment::SplitAdvance
    sPrev = next;
    tPrev = t;
  }
  return splitAcc;
}

//PSI::SegmentSplit::Integrate
  writeColor(integrateSplit(sf, sb, max(D, 0.0), pFront, rayDir));
  return;
