//PSI::IsoPerFragment::Dec
// Per-fragment isosurfaces (Maximo et al. 2010 §3.4, "per-pixel"): the segment is split at the
// isovalues it crosses (PsiSegmentSplitFS.glsl) and the lit surface is composited at its depth
// (Röttger et al. 2000 §10: the part in front, the surface, the part behind). An isovalue counts
// on [front, back) of a segment, so that a crossing on a face shared by two cells is drawn once.
uniform float isoValues[PSI_ISO_COUNT]; // ascending
flat in vec3 isoG0;
flat in mat3 isoJ;
flat in vec3 isoV0;

// Isosurface i at view point p: the normal from the linear gradient field of the cell.
vec4 isoSurface(int i, vec3 p, vec3 dir)
{
  return isoShade(i, isoG0 + isoJ * (p - isoV0), dir);
}

//PSI::IsoPerFragment::Impl
  frontRay(pFront, rayDir);

//PSI::IsoPerFragment::SplitInit
  int iStep = ds >= 0.0 ? 1 : -1;
  int ii = ds >= 0.0 ? 0 : PSI_ISO_COUNT - 1;
  while (ii >= 0 && ii < PSI_ISO_COUNT && dirS * (isoValues[ii] - sf) < 0.0)
  {
    ii += iStep;
  }

//PSI::IsoPerFragment::SplitNext
    if (ii >= 0 && ii < PSI_ISO_COUNT && dirS * (sb - isoValues[ii]) > 0.0 &&
      dirS * (next - isoValues[ii]) >= 0.0)
    {
      next = isoValues[ii];
      kind = 2;
    }

//PSI::IsoPerFragment::SplitAdvance
    if (kind == 2)
    {
      splitAcc += (1.0 - splitAcc.a) * isoSurface(ii, p0 + (t * D) * dir, dir);
      ii += iStep;
      if (splitAcc.a >= 1.0)
      {
        break; // an opaque isosurface stops the ray
      }
    }
