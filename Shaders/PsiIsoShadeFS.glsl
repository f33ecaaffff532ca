//PSI::IsoShade::Dec
// Isosurface shading, common to marching tetrahedra and per-fragment isosurfaces.
uniform vec3 isoColors[PSI_ISO_COUNT];
uniform float isoOpacities[PSI_ISO_COUNT]; // each surface's own
uniform int isoLighting;
uniform int lightCount;
uniform vec3 lightDirVC[PSI_MAX_LIGHTS]; // direction the light travels, view coordinates
uniform vec3 lightColor[PSI_MAX_LIGHTS]; // diffuse color * intensity

// Premultiplied color of isosurface i with normal n (any length), seen along dir: two-sided
// diffuse lighting with the renderer's lights (VTK's Phong without ambient and specular:
// ParaView's defaults).
vec4 isoShade(int i, vec3 n, vec3 dir)
{
  vec3 c = isoColors[i];
  if (isoLighting == 1)
  {
    float nn = dot(n, n);
    n = nn > 1e-37 ? n * inversesqrt(nn) : -dir;
    n = dot(n, dir) > 0.0 ? -n : n;
    vec3 lit = vec3(0.0);
    for (int k = 0; k < lightCount; ++k)
    {
      lit += lightColor[k] * max(dot(n, -lightDirVC[k]), 0.0);
    }
    c *= lit;
  }
  return vec4(c * isoOpacities[i], isoOpacities[i]);
}
