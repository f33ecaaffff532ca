//PSI::SeparateOpacity::Dec
// A separate opacity array (ParaView's UseSeparateOpacityArray): the integrators take the color
// at each end of the segment from the color scalar and the attenuation from the opacity scalar
// there (transferFront / transferBack, PsiTransferTableFS.glsl). Both scalars are linear along
// the segment, so every clipping of the segment (opaque geometry, isosurface pieces, split
// points) moves the opacity ends by the same fractions as the color ends.
flat in vec4 opacityPlane;                // o(x) = g_o . x + o0, view coordinates
uniform vec2 tfOpacityScaleShift;         // opacity scalar -> table coordinate (attenuation)
uniform samplerBuffer opacityScalars;     // per point (near-plane clipping fetches them)
float opacityFront = 0.0, opacityBack = 0.0; // the opacity scalar at the segment's two ends

//PSI::SeparateOpacity::Front
  v.a = texture(transferFunction, opacityFront * tfOpacityScaleShift.x + tfOpacityScaleShift.y).a;

//PSI::SeparateOpacity::Back
  v.a = texture(transferFunction, opacityBack * tfOpacityScaleShift.x + tfOpacityScaleShift.y).a;

//PSI::SeparateOpacity::Segment
  opacityFront = dot(opacityPlane.xyz, rayOrigin + rayEntry * rayStep) + opacityPlane.w;
  opacityBack = dot(opacityPlane.xyz, rayOrigin + rayExit * rayStep) + opacityPlane.w;

//PSI::SeparateOpacity::OpaqueClip
      opacityBack = mix(opacityFront, opacityBack, toOpaque / max(D, 1e-30));

//PSI::SeparateOpacity::Piece
  float oPiece0 = mix(opacityFront, opacityBack, t0), oPiece1 = mix(opacityFront, opacityBack, t1);
  opacityFront = oPiece0;
  opacityBack = oPiece1;

//PSI::SeparateOpacity::DepthPeel
  float oPeel0 = mix(opacityFront, opacityBack, t0), oPeel1 = mix(opacityFront, opacityBack, t1);
  opacityFront = oPeel0;
  opacityBack = oPeel1;

//PSI::SeparateOpacity::SplitInit
  float splitOpacityFront = opacityFront, splitOpacityBack = opacityBack;

//PSI::SeparateOpacity::SplitPiece
    opacityFront = mix(splitOpacityFront, splitOpacityBack, tPrev);
    opacityBack = mix(splitOpacityFront, splitOpacityBack, t);

//PSI::SeparateOpacity::NearClip
  vec4 tetO = vec4(texelFetch(opacityScalars, clipTet.x).r, texelFetch(opacityScalars, clipTet.y).r,
    texelFetch(opacityScalars, clipTet.z).r, texelFetch(opacityScalars, clipTet.w).r);
  vec3 gO = toGradient * (tetO.yzw - tetO.x);
  opacityFront = tetO.x + dot(gO, pf - V[0]);
  opacityBack = tetO.x + dot(gO, pb - V[0]);
