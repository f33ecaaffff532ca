//VTK::System::Dec
//VTK::Output::Dec
// PsiVolumeFS: integrates the ray segment through one tetrahedron (front scalar, back scalar,
// thickness interpolated from the geometry shader) and outputs premultiplied color, blended
// back to front with (ONE, ONE_MINUS_SRC_ALPHA) into a floating-point target.

noperspective in vec3 segment;

uniform sampler2D transferFunction; // N x 1, rgb = luminance, a = attenuation (1/length)
uniform vec2 tfScaleShift;          // texcoord = s * scale + shift (texel centers)
uniform sampler2D psiTable;         // Psi(gamma_b, gamma_f), seed 000 Eq. 12
uniform vec2 psiScaleShift;         // texcoord = gamma * scale + shift (texel centers)
uniform sampler2D sceneDepth;       // depth of the opaque geometry already drawn
uniform mat4 DCVCMatrix;            // inverse projection: window depth -> view distance
uniform vec2 viewportSize;

vec4 transfer(float s)
{
  return texture(transferFunction, vec2(s * tfScaleShift.x + tfScaleShift.y, 0.5));
}

// gamma = tau D / (tau D + 1) (seed 000 Eq. 11), written so that tau D = inf gives 1, not NaN.
vec2 gammaOf(vec2 tauD)
{
  return 1.0 - 1.0 / (tauD + 1.0);
}

//PSI::Integrator::Impl

vec3 viewPointAt(float depth)
{
  vec4 ndc = vec4(2.0 * gl_FragCoord.xy / viewportSize - 1.0, 2.0 * depth - 1.0, 1.0);
  vec4 p = DCVCMatrix * ndc;
  return p.xyz / p.w;
}

void main()
{
  float sf = segment.x, sb = segment.y, D = segment.z;
  // Opaque geometry: nothing behind it is seen, and a cell it cuts is integrated only up to it.
  float opaque = texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r;
  if (gl_FragCoord.z >= opaque)
  {
    discard;
  }
  if (opaque < 1.0)
  {
    float toOpaque = distance(viewPointAt(gl_FragCoord.z), viewPointAt(opaque));
    if (toOpaque < D)
    {
      sb = mix(sf, sb, toOpaque / max(D, 1e-30));
      D = toOpaque;
    }
  }
  vec4 c = integrateSegment(sf, sb, max(D, 0.0));
  if (!(c.a > 0.0))
  {
    discard; // fully transparent, or a NaN that must not reach the image
  }
  gl_FragData[0] = c;
}
