//PSI::PointIds::Impl
  // Isosurface and near-plane variants: the point ids go on to the geometry shader (smoothed
  // point gradients as isosurface normals; the fragment shader's exact clipping of a cut cell).
  tetOut.ids = tetPointIds;
