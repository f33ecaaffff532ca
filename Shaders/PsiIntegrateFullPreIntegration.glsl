// Full pre-integration (Röttger et al. 2000): the segment's premultiplied color and
// opacity looked up in a 3D table over (front scalar, back scalar, length), built for the current
// transfer function (PsiPreIntegrationTable.cxx). Captures transfer-function detail inside a cell
// up to the table's resolution; its rebuild on every transfer-function edit is part of its cost.
// The length coordinate is logarithmic (Kraus, Qiao & Ebert 2004), as
// psi::PreIntegrationLengthAxis::Index: sample 0 is l = 0, then geometric from l_min to l_max.
float preLengthCoord(float D)
{
  float x = max(D, 0.0) * preLengthAxis.x;
  float k = x < 1.0 ? x : 1.0 + log(x) * preLengthAxis.y;
  return (min(k, preLengthAxis.z) + 0.5) * preLengthAxis.w;
}

vec4 integrateSegment(float sf, float sb, float D)
{
  vec3 coord = vec3(sf * preScalarScaleShift.x + preScalarScaleShift.y,
    sb * preScalarScaleShift.x + preScalarScaleShift.y, preLengthCoord(D));
  return texture(preIntegrated, coord);
}
