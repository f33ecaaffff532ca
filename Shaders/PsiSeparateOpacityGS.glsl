//PSI::SeparateOpacity::Dec
// A separate opacity array: color from one scalar, opacity from another, both linear over the
// cell. Early discard is judged on the opacity scalar's range; isosurfaces stay on the color
// scalar. Drawn with silhouettes (PsiRaySegments*.glsl), whose fragments evaluate the opacity
// scalar's plane at their segment's ends as they do the color scalar's.
// The flat output opacityPlane, o(x) = g_o . x + o0 in view coordinates, is declared by
// psi::GeometryOutputs (PsiStageInterface.cxx).
vec3 opacityGradient = vec3(0.0);

//PSI::SeparateOpacity::Gradient
    // the opacity scalar's gradient, by the same Cramer's rule as the color scalar's
    vec4 ov = tetIn[0].opacity;
    opacityGradient = degenerate
      ? vec3(0.0)
      : ((ov.y - ov.x) * c23 + (ov.z - ov.x) * c31 + (ov.w - ov.x) * c12) / det;

//PSI::SeparateOpacity::Vertex
  opacityPlane = vec4(opacityGradient, tetIn[0].opacity.x - dot(opacityGradient, viewP[0]));

//PSI::SeparateOpacity::Range
  vec4 cornerOpacity = tetIn[0].opacity;
  dmin = min(min(cornerOpacity.x, cornerOpacity.y), min(cornerOpacity.z, cornerOpacity.w));
  dmax = max(max(cornerOpacity.x, cornerOpacity.y), max(cornerOpacity.z, cornerOpacity.w));
