//PSI::Transfer::Impl
// The transfer function as its nodes (psi::TransferFunctionNodes: the functions' own values at
// their bends and steps, refined where a color map bends), for adaptive sampling
// (PsiAdaptiveFS.glsl, Moreland 2004, dissertation, §4.3): the segment is split at the nodes, so
// that each piece lies in one node interval, where color and attenuation are linear and are
// interpolated between its two nodes: each piece is integrated exactly, however narrow.
uniform float tfNodes[PSI_TF_NODES_MAX];     // ascending (equal at a step), from range end to end
uniform vec4 tfNodeValues[PSI_TF_NODES_MAX]; // L.r, L.g, L.b, tau at each node
uniform int tfNodeCount;
int tfPiece = 0; // the node interval [tfPiece, tfPiece + 1] of the piece being integrated

// Linear between the two nodes of the current piece's interval; clamped beyond the range.
vec4 transfer(float s)
{
  int a = clamp(tfPiece, 0, tfNodeCount - 1);
  int b = clamp(tfPiece + 1, 0, tfNodeCount - 1);
  float width = tfNodes[b] - tfNodes[a];
  float w = width > 0.0 ? clamp((s - tfNodes[a]) / width, 0.0, 1.0) : 0.0;
  return mix(tfNodeValues[a], tfNodeValues[b], w);
}

// The transfer function at the segment's front and back ends (the integrators' inputs).
vec4 transferFront(float s)
{
  return transfer(s);
}

vec4 transferBack(float s)
{
  return transfer(s);
}
