// PsiSamplesPassed: one GL_SAMPLES_PASSED query, the samples that pass the depth test between
// Begin and End, read by Take when wanted (it waits for those draws). The render target counts
// with it the pixels each opacity mask finds opaque, read a stride later; the mapper, as a
// testing aid, the volume's own samples: front to back, the fragments behind opaque pixels fail
// the depth test before they are shaded.
#ifndef PsiSamplesPassed_h
#define PsiSamplesPassed_h

#include <cstdint>

class PsiSamplesPassed
{
public:
  PsiSamplesPassed() = default;
  ~PsiSamplesPassed();
  /// Starts counting (the query is made on first use, in the current context).
  void Begin();
  /// Stops counting; the count is pending until Take. Nothing when not counting.
  void End();
  bool IsPending() const { return this->Pending; }
  /// The pending count (waits for the draws it counts), and no longer pending; 0 when none is.
  uint64_t Take();
  void ReleaseGraphicsResources();

private:
  PsiSamplesPassed(const PsiSamplesPassed&) = delete;
  void operator=(const PsiSamplesPassed&) = delete;
  unsigned int Query = 0;
  bool Counting = false;
  bool Pending = false;
};

#endif
