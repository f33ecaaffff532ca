//PSI::IsoSmoothNormals::Dec
// Isosurface normals, smooth shading: the gradient field interpolated linearly from the smoothed
// point gradients (view coordinates).
uniform samplerBuffer pointGradients; // model-space (shifted) gradient per point
uniform mat3 normalMatrix;            // model -> view for gradients (inverse transpose)
vec3 pointNormal[4] = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));

void fetchNormals()
{
  for (int k = 0; k < 4; ++k)
  {
    pointNormal[k] = normalMatrix * texelFetch(pointGradients, int(tetIn[0].ids[k])).xyz;
  }
}
