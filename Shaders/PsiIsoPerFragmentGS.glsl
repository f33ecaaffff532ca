//PSI::IsoPerFragment::Dec
// Per-fragment isosurfaces (the "per-pixel" strategy of Maximo et al. 2010 §3.4): the fragment
// shader meets the surface exactly along each ray; the normal field g(x) = isoG0 + isoJ (x - isoV0)
// is passed flat (outputs declared by psi::GeometryOutputs, PsiStageInterface.cxx).
vec3 tetIsoG0 = vec3(0.0);
mat3 tetIsoJ = mat3(0.0);

//PSI::IsoPerFragment::Flat
  isoG0 = tetIsoG0;
  isoJ = tetIsoJ;
  isoV0 = viewP[0];

//PSI::IsoPerFragment::Impl
  fetchNormals();
  {
    mat3 E = mat3(viewP[1] - viewP[0], viewP[2] - viewP[0], viewP[3] - viewP[0]);
    float det = determinant(E);
    float scale = max(max(dot(E[0], E[0]), dot(E[1], E[1])), dot(E[2], E[2]));
    tetIsoG0 = pointNormal[0];
    // J E = [n1-n0 n2-n0 n3-n0]; a degenerate cell keeps the vertex gradient (flat shading).
    tetIsoJ = abs(det) > 1e-7 * scale * sqrt(scale) ?
      mat3(pointNormal[1] - pointNormal[0], pointNormal[2] - pointNormal[0],
        pointNormal[3] - pointNormal[0]) * inverse(E) : mat3(0.0);
  }
