// Full pre-integration (Röttger et al. 2000): the segment's premultiplied color and
// opacity looked up in a 3D table over (front scalar, back scalar, length), built for the current
// transfer function (PsiPreIntegrationTable.cxx). Captures transfer-function detail inside a cell
// up to the table's resolution; its rebuild on every transfer-function edit is part of its cost.
vec4 integrateSegment(float sf, float sb, float D)
{
  vec3 coord = vec3(sf * preScalarScaleShift.x + preScalarScaleShift.y,
    sb * preScalarScaleShift.x + preScalarScaleShift.y,
    min(D * preLengthScaleShift.x + preLengthScaleShift.y, 1.0));
  return texture(preIntegrated, coord);
}
