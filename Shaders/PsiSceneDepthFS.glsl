//PSI::SceneDepth::Dec
// The depth of the opaque geometry (opaque clipping and near-plane clipping).
uniform sampler2D sceneDepth;

//PSI::SceneDepth::Impl
  float opaque = texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r;
  if (frontDepth >= opaque)
  {
    discard;
  }
