//PSI::Adaptive::Dec
// Adaptive sampling (Moreland 2004, dissertation, §4.3): the segment is split at the transfer
// function's nodes (PsiSegmentSplitFS.glsl), so that color and attenuation are linear on each
// piece.
uniform float tfNodes[PSI_TF_NODES_MAX]; // ascending, strictly inside the scalar range
uniform int tfNodeCount;

//PSI::Adaptive::SplitInit
  int nStep = ds >= 0.0 ? 1 : -1;
  int ni = ds >= 0.0 ? 0 : tfNodeCount - 1;
  while (ni >= 0 && ni < tfNodeCount && dirS * (tfNodes[ni] - sf) <= 0.0)
  {
    ni += nStep;
  }

//PSI::Adaptive::SplitNext
    if (ni >= 0 && ni < tfNodeCount && dirS * (sb - tfNodes[ni]) > 0.0)
    {
      next = tfNodes[ni];
      kind = 1;
    }

//PSI::Adaptive::SplitAdvance
    if (kind == 1)
    {
      ni += nStep;
    }
