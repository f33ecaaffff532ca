//PSI::IsoFlatNormals::Dec
// Isosurface normals, flat shading: the cell's own gradient at all four vertices.
vec3 pointNormal[4] = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));

void fetchNormals()
{
  for (int k = 0; k < 4; ++k)
  {
    pointNormal[k] = gradient; // flat shading: the cell's gradient
  }
}
