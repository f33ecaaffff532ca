//PSI::CellGradient::Dec
// The gradient of the cell's linear scalar, view coordinates (exact segments and isosurfaces).
vec3 gradient = vec3(0.0);

//PSI::CellGradient::Impl
  {
    // s(x) = s0 + g . (x - V0) with g from the three edge equations (Cramer's rule).
    vec3 e1 = viewP[1] - viewP[0], e2 = viewP[2] - viewP[0], e3 = viewP[3] - viewP[0];
    vec3 c23 = cross(e2, e3), c31 = cross(e3, e1), c12 = cross(e1, e2);
    float det = dot(e1, c23);
    float scale = max(max(dot(e1, e1), dot(e2, e2)), dot(e3, e3));
    bool degenerate = abs(det) <= 1e-7 * scale * sqrt(scale);
//PSI::ExactSegments::Degenerate
//PSI::RaySegments::Degenerate
//PSI::IsoTriangles::Degenerate
    gradient = degenerate ? vec3(0.0)
                          : ((scalar[1] - scalar[0]) * c23 + (scalar[2] - scalar[0]) * c31 +
                              (scalar[3] - scalar[0]) * c12) / det;
//PSI::SeparateOpacity::Gradient
  }
