//PSI::EarlyDiscard::Dec
// Early discard (Maximo et al. 2010 §3.5): a tetrahedron whose scalar range meets only
// zero-opacity samples of the (linearly interpolated) transfer function contributes nothing and
// emits nothing. opacityPrefix[i] counts the samples 0..i with non-zero opacity.
uniform sampler2D opacityPrefix;
uniform vec2 tfIndexScaleShift; // scalar -> sample index
uniform int tfSamples;

bool transparentRange(float smin, float smax)
{
  int i0 = clamp(int(floor(smin * tfIndexScaleShift.x + tfIndexScaleShift.y)), 0, tfSamples - 1);
  int i1 = clamp(int(ceil(smax * tfIndexScaleShift.x + tfIndexScaleShift.y)), 0, tfSamples - 1);
  float before = i0 > 0 ? texelFetch(opacityPrefix, ivec2(i0 - 1, 0), 0).r : 0.0;
  return texelFetch(opacityPrefix, ivec2(i1, 0), 0).r - before < 0.5;
}

//PSI::EarlyDiscard::Cell
  // The whole cell (without marching-tetrahedra isosurfaces, whose pieces are tested one by one);
  // with a separate opacity array, its range of the opacity scalar.
  if (transparentRange(dmin, dmax))
  {
    return;
  }

//PSI::EarlyDiscard::Piece
  // One volume piece between two isovalues (its surfaces are drawn regardless).
  float lo = j > 0 && j <= PSI_ISO_COUNT ? max(isoValues[j - 1], smin) : smin;
  float hi = j < PSI_ISO_COUNT ? min(isoValues[j], smax) : smax;
  if (transparentRange(lo, hi))
  {
    return;
  }
