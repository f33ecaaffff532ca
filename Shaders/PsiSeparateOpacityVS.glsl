//PSI::SeparateOpacity::Dec
// A separate opacity array (ParaView's UseSeparateOpacityArray; PsiSeparateOpacity{GS,FS}.glsl):
// the opacity scalar of each point, fetched by id as the points are.
uniform samplerBuffer opacityScalars;

//PSI::SeparateOpacity::Impl
  tetOut.opacity = vec4(texelFetch(opacityScalars, int(tetPointIds.x)).r,
    texelFetch(opacityScalars, int(tetPointIds.y)).r, texelFetch(opacityScalars, int(tetPointIds.z)).r,
    texelFetch(opacityScalars, int(tetPointIds.w)).r);
