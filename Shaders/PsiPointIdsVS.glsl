//PSI::PointIds::Dec
// Isosurface and near-plane variants: the point ids go on to the geometry shader (smoothed point
// gradients as isosurface normals; the fragment shader's exact clipping of a cut cell).
flat out uvec4 vsIds;

//PSI::PointIds::Impl
  vsIds = tetPointIds;
