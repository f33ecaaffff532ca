//PSI::SeparateOpacity::Dec
// A separate opacity array: color from one scalar, opacity from another, both linear over the
// cell. Early discard is judged on the opacity scalar's range; isosurfaces stay on the color
// scalar. Drawn with silhouettes (PsiRaySegments*.glsl), whose fragments evaluate the opacity
// scalar's plane at their segment's ends as they do the color scalar's.
in vec4 vsOpacity[];
flat out vec4 opacityPlane; // o(x) = g_o . x + o0, view coordinates
vec3 opacityGradient = vec3(0.0);

//PSI::SeparateOpacity::Gradient
    // the opacity scalar's gradient, by the same Cramer's rule as the color scalar's
    vec4 ov = vsOpacity[0];
    opacityGradient = degenerate
      ? vec3(0.0)
      : ((ov.y - ov.x) * c23 + (ov.z - ov.x) * c31 + (ov.w - ov.x) * c12) / det;

//PSI::SeparateOpacity::Vertex
  opacityPlane = vec4(opacityGradient, vsOpacity[0].x - dot(opacityGradient, viewP[0]));

//PSI::SeparateOpacity::Range
  dmin = min(min(vsOpacity[0].x, vsOpacity[0].y), min(vsOpacity[0].z, vsOpacity[0].w));
  dmax = max(max(vsOpacity[0].x, vsOpacity[0].y), max(vsOpacity[0].z, vsOpacity[0].w));
