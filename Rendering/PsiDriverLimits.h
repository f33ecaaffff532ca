// PsiDriverLimits: the OpenGL driver's limits on the buffers 'Psi Volume' fills: the points (and
// their opacity scalars and gradients) go to the GPU as texture buffers, one texel per point
// (GL_MAX_TEXTURE_BUFFER_SIZE: 134,217,728 on llvmpipe and common GPU drivers); the compute
// projector writes each pass's triangles to shader storage blocks
// (GL_MAX_SHADER_STORAGE_BLOCK_SIZE: 128 MiB on llvmpipe). A mesh past the first is not drawn,
// with one message naming the limit; the compute projector draws in as many passes as the second
// needs. Tests lower them (vtkPsiVolumeMapper::SetDriverLimitsForTesting) to cross them with a
// small mesh.
#ifndef PsiDriverLimits_h
#define PsiDriverLimits_h

#include <algorithm>

struct PsiDriverLimits
{
  long long MaxTextureBufferTexels = 0; ///< GL_MAX_TEXTURE_BUFFER_SIZE
  long long MaxStorageBlockBytes = 0;   ///< GL_MAX_SHADER_STORAGE_BLOCK_SIZE, 0 without OpenGL 4.3

  /// The current context's limits.
  static PsiDriverLimits Query();
  /// These limits, each lowered to `lower`'s where that one is positive.
  PsiDriverLimits LoweredTo(const PsiDriverLimits& lower) const
  {
    PsiDriverLimits l = *this;
    if (lower.MaxTextureBufferTexels > 0)
    {
      l.MaxTextureBufferTexels = std::min(l.MaxTextureBufferTexels, lower.MaxTextureBufferTexels);
    }
    if (lower.MaxStorageBlockBytes > 0)
    {
      l.MaxStorageBlockBytes = std::min(l.MaxStorageBlockBytes, lower.MaxStorageBlockBytes);
    }
    return l;
  }
};

#endif
