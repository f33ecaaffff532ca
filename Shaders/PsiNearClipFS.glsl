//PSI::NearClip::Dec
// Near-plane clipping (PsiNearClipGS.glsl): a cell cut by the near plane arrives as a screen box
// with its point ids, and each ray is intersected with the tetrahedron exactly.
flat in ivec4 clipTet; // point ids of a cell cut by the near plane, x = -1 otherwise
uniform samplerBuffer points; // xyz: model (shifted) coordinates, w: scalar in [0, 1]
uniform mat4 MCVCMatrix;

vec4 clipVertex(int id)
{
  vec4 p = texelFetch(points, id);
  return vec4((MCVCMatrix * vec4(p.xyz, 1.0)).xyz, p.w);
}

// Exact ray / tetrahedron intersection for a cell cut by the near plane: the ray starts on the
// near plane at this pixel; each face plane bounds the parameter interval [tin, tout].
bool clipSegment(out float sf, out float sb, out float D, out float frontDepth, out vec3 pFront,
  out vec3 rayDir)
{
  vec4 tetV0 = clipVertex(clipTet.x), tetV1 = clipVertex(clipTet.y);
  vec4 tetV2 = clipVertex(clipTet.z), tetV3 = clipVertex(clipTet.w);
  vec3 V[4] = vec3[4](tetV0.xyz, tetV1.xyz, tetV2.xyz, tetV3.xyz);
  vec3 o = viewPointAt(0.0);
  vec3 dir = parallelProjection == 1 ? vec3(0.0, 0.0, -1.0) : normalize(o);
  float tin = 0.0, tout = 1e30;
  for (int i = 0; i < 4; ++i)
  {
    vec3 a = V[(i + 1) % 4], b = V[(i + 2) % 4], c = V[(i + 3) % 4];
    vec3 n = cross(b - a, c - a);
    if (dot(n, V[i] - a) > 0.0)
    {
      n = -n; // outward
    }
    float den = dot(n, dir);
    float num = dot(n, a - o);
    if (abs(den) < 1e-30)
    {
      if (num < 0.0)
      {
        return false; // parallel to the face and outside it
      }
      continue;
    }
    float t = num / den;
    if (den < 0.0)
    {
      tin = max(tin, t);
    }
    else
    {
      tout = min(tout, t);
    }
  }
  if (!(tout > tin))
  {
    return false;
  }
  // Linear scalar: s(x) = s0 + g . (x - V0), g from the three edge equations.
  mat3 E = mat3(V[1] - V[0], V[2] - V[0], V[3] - V[0]);
  vec3 ds = vec3(tetV1.w - tetV0.w, tetV2.w - tetV0.w, tetV3.w - tetV0.w);
  mat3 toGradient = inverse(transpose(E)); // differences from V0 at V1..V3 -> gradient
  vec3 g = toGradient * ds;
  vec3 pf = o + tin * dir, pb = o + tout * dir;
  sf = tetV0.w + dot(g, pf - V[0]);
  sb = tetV0.w + dot(g, pb - V[0]);
//PSI::SeparateOpacity::NearClip
  D = tout - tin;
  pFront = pf;
  rayDir = dir;
  vec4 c = VCDCMatrix * vec4(pf, 1.0);
  frontDepth = 0.5 * c.z / c.w + 0.5;
  return true;
}

//PSI::NearClip::Impl
  if (clipTet.x >= 0 && !clipSegment(sf, sb, D, frontDepth, pFront, rayDir))
  {
    discard;
  }
