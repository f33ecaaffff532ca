//PSI::OpaqueClip::Impl
  // Where opaque geometry cuts through the volume, a cell it cuts is integrated only up to it
  // (`opaque`: the scene's depth at this pixel, PsiSceneDepthFS.glsl).
  if (opaque < 1.0)
  {
    float toOpaque = distance(viewPointAt(frontDepth), viewPointAt(opaque));
    if (toOpaque < D)
    {
//PSI::SeparateOpacity::OpaqueClip
      sb = mix(sf, sb, toOpaque / max(D, 1e-30));
      D = toOpaque;
    }
  }
