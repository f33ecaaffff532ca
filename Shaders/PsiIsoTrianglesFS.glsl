//PSI::IsoTriangles::Dec
// Marching-tetrahedra isosurfaces from the geometry shader (PsiIsoTrianglesGS.glsl, Maximo et
// al. 2010 §3.4): a volume fragment integrates only the part of its segment inside its piece's
// scalar interval [lo, hi); a surface fragment is the lit surface (normal interpolated from the
// polygon's vertices).
flat in float piece; // >= 0 a volume piece, < 0 a surface
uniform float isoValues[PSI_ISO_COUNT]; // ascending

bool clipToPiece(inout float sf, inout float sb, inout float D)
{
  int j = int(piece + 0.5);
  if (j > PSI_ISO_COUNT)
  {
    return true; // the whole cell
  }
  const float big = 3.0e38;
  vec2 range = vec2(j > 0 ? isoValues[j - 1] : -big, j < PSI_ISO_COUNT ? isoValues[j] : big);
  float ds = sb - sf;
  if (ds == 0.0)
  {
    return sf >= range.x && sf < range.y;
  }
  float ta = clamp((range.x - sf) / ds, 0.0, 1.0), tb = clamp((range.y - sf) / ds, 0.0, 1.0);
  float t0 = min(ta, tb), t1 = max(ta, tb);
  if (!(t1 > t0))
  {
    return false;
  }
  float s0 = sf + t0 * ds, s1 = sf + t1 * ds;
//PSI::SeparateOpacity::Piece
  sf = s0;
  sb = s1;
  D *= t1 - t0;
  return true;
}

//PSI::IsoTriangles::Surface
  if (piece < 0.0)
  {
    // An isosurface fragment (hidden by opaque geometry through the depth test).
//PSI::DepthPeel::Surface
    vec3 p = viewPointAt(gl_FragCoord.z);
    vec3 dir = parallelProjection == 1 ? vec3(0.0, 0.0, -1.0) : normalize(p);
    vec3 n = surfaceNormal();
    gl_FragData[0] = isoShade(int(-piece - 0.5), n, dir);
    return;
  }

//PSI::IsoTriangles::Impl
  if (!clipToPiece(sf, sb, D))
  {
    discard;
  }
