//PSI::DepthPeel::Dec
// Translucent geometry through VTK's dual depth peeling (vtkDualDepthPeelingPass, with
// ParaView's DepthPeelingForVolumes): the pass renders the volume in each of its stages and
// expects the volume between given window depths of each pixel, as its GPU ray caster casts
// rays between them. Here each draw of the tetrahedra integrates only the part of every ray
// segment inside one depth interval: the segment is clipped to it, as opaque geometry clips it,
// and the clipped segment is integrated exactly (the scalars are linear along it). The interval
// comes from the pass's depth textures, by the pass's own rules for its stages (its
// PreReplaceVolumetricShaderValues):
//   peelStage 1, before the peels: in front of all translucent layers (the front image) and
//     behind them, up to opaque geometry (the back image);
//   peelStage 2, a peel: from the front layer just peeled to the next one (front), and from the
//     next back layer to the back layer just peeled (back);
//   peelStage 3, the final alpha blend: what lies between the layers not peeled.
// (PsiDepthPeelingCalls.h finds the stage; PsiCompositeFS.glsl hands the images to the pass.)
uniform int peelStage;               // 1, 2, 3 as above
uniform int peelRange;               // 0 the back image, 1 the front image
uniform sampler2D outerDepthTex;     // the pass's depth textures: (-near, far) per pixel
uniform sampler2D innerDepthTex;
uniform sampler2D opaqueDepthTex;
uniform sampler2D depthRangeTex;

// The window-depth interval [x, y] this draw integrates at this pixel (empty when x >= y).
vec2 peelDepthRange()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  const vec2 none = vec2(1.0, -1.0);
  if (peelStage == 3)
  {
    vec2 r = texelFetch(depthRangeTex, pixel, 0).xy;
    return r.x == -1.0 ? none : vec2(-r.x, r.y);
  }
  vec2 inner = texelFetch(innerDepthTex, pixel, 0).xy;
  vec2 outer = texelFetch(outerDepthTex, pixel, 0).xy;
  if (peelStage == 1)
  {
    bool opaque = outer.y >= 0.0, translucent = inner.x != -1.0;
    if (peelRange == 1)
    {
      return translucent ? vec2(0.0, -inner.x) : none;
    }
    return !translucent ? vec2(0.0, opaque ? inner.y : 1.0)
                        : vec2(inner.y, opaque ? outer.y : 1.0);
  }
  if (outer.x == -1.0)
  {
    return none; // no layer left here
  }
  vec2 front = vec2(-outer.x, -inner.x), back = vec2(inner.y, outer.y);
  bool onlyBack = front == back;
  bool noInner = inner.x == -1.0;
  front.y = noInner ? outer.y : front.y;
  float opaqueDepth = texelFetch(opaqueDepthTex, pixel, 0).x;
  bool endBehindOpaque = front.y >= opaqueDepth;
  front.y = endBehindOpaque ? opaqueDepth : front.y;
  if (peelRange == 1)
  {
    return onlyBack ? none : front;
  }
  return endBehindOpaque || noInner ? none : back;
}

// The ray parameter t (rayOrigin + t rayStep) of this pixel's point at window depth z.
float rayTAtDepth(float z)
{
  vec3 p = viewPointAt(z);
  return dot(p - rayOrigin, rayStep) / dot(rayStep, rayStep);
}

//PSI::DepthPeel::Early
  // A silhouette lies at its tetrahedron's nearest depth: a fragment whose interval is empty,
  // or ends in front of that depth, has nothing to integrate.
  vec2 peelRange = peelDepthRange();
  if (!(peelRange.x < peelRange.y) || gl_FragCoord.z > peelRange.y)
  {
    discard;
  }

//PSI::DepthPeel::Impl
  // Keep the part of the segment inside this draw's depth interval.
  {
    float len = length(rayStep);
    float tIn = rayEntry, tOut = rayEntry + D / max(len, 1e-30);
    float a = max(tIn, rayTAtDepth(peelRange.x)), b = min(tOut, rayTAtDepth(peelRange.y));
    if (!(b > a)) // (an empty interval was dropped first: Early)
    {
      discard;
    }
    float span = max(tOut - tIn, 1e-30);
    float t0 = clamp((a - tIn) / span, 0.0, 1.0), t1 = clamp((b - tIn) / span, 0.0, 1.0);
//PSI::SeparateOpacity::DepthPeel
    float s0 = mix(sf, sb, t0), s1 = mix(sf, sb, t1);
    sf = s0;
    sb = s1;
    D = (b - a) * len;
    rayEntry = a;
    frontDepth = segmentFrontDepth();
  }

//PSI::DepthPeel::Surface
    // A marching-tetrahedra surface belongs to the draw whose depth interval holds it.
    vec2 surfaceRange = peelDepthRange();
    if (!(gl_FragCoord.z >= surfaceRange.x && gl_FragCoord.z < surfaceRange.y))
    {
      discard;
    }
