//PSI::PointIds::Dec
// The tetrahedron's point ids, from the vertex shader (isosurface normals, near-plane clipping).
flat in uvec4 vsIds[];
