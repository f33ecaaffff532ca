//PSI::SeparateOpacity::Dec
// A separate opacity array (ParaView's UseSeparateOpacityArray; PsiSeparateOpacity{GS,FS}.glsl):
// the opacity scalar of each point, fetched by id as the points are.
uniform samplerBuffer opacityScalars;
out vec4 vsOpacity; // the opacity scalars of the tetrahedron's four points

//PSI::SeparateOpacity::Impl
  vsOpacity = vec4(texelFetch(opacityScalars, int(tetPointIds.x)).r,
    texelFetch(opacityScalars, int(tetPointIds.y)).r, texelFetch(opacityScalars, int(tetPointIds.z)).r,
    texelFetch(opacityScalars, int(tetPointIds.w)).r);
