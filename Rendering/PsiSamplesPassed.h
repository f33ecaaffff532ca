// PsiSamplesPassed: counts the samples that pass the depth test over several draws
// (GL_SAMPLES_PASSED queries, summed), a testing aid: front to back, the fragments behind opaque
// pixels fail the depth test before they are shaded, so fewer samples pass.
#ifndef PsiSamplesPassed_h
#define PsiSamplesPassed_h

#include <cstdint>

class PsiSamplesPassed
{
public:
  PsiSamplesPassed() = default;
  ~PsiSamplesPassed();
  /// Starts counting (a no-op when `on` is false: then Total stays 0).
  void Begin(bool on);
  /// Stops counting and adds what passed since Begin to Total (waits for the draws).
  void End();
  uint64_t GetTotal() const { return this->Total; }
  void Reset() { this->Total = 0; }
  void ReleaseGraphicsResources();

private:
  PsiSamplesPassed(const PsiSamplesPassed&) = delete;
  void operator=(const PsiSamplesPassed&) = delete;
  unsigned int Query = 0;
  bool Counting = false;
  uint64_t Total = 0;
};

#endif
