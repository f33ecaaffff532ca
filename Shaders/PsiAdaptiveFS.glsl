//PSI::Adaptive::SplitInit
// Adaptive sampling (Moreland 2004, dissertation, §4.3): the segment is split at the transfer
// function's nodes (tfNodes, PsiTransferNodesFS.glsl; the split loop is PsiSegmentSplitFS.glsl),
// and each piece's transfer() reads the node interval tfPiece it lies in.
  // ni: the first node beyond sf along the segment. Ascending, the first node above sf; descending,
  // the last node below it. Binary search for the first node above sf (at or above it, descending).
  int nStep = ds >= 0.0 ? 1 : -1;
  int lo = 0, hi = tfNodeCount;
  while (lo < hi)
  {
    int mid = (lo + hi) / 2;
    bool below = ds >= 0.0 ? tfNodes[mid] <= sf : tfNodes[mid] < sf;
    lo = below ? mid + 1 : lo;
    hi = below ? hi : mid;
  }
  int ni = ds >= 0.0 ? lo : lo - 1;

//PSI::Adaptive::SplitNext
    // ascending, the piece lies below node ni; descending, above it
    tfPiece = nStep > 0 ? ni - 1 : ni;
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
