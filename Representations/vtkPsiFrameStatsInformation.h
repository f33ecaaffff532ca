/**
 * @class   vtkPsiFrameStatsInformation
 * @brief   Statistics of the last frame of a vtkPsiVolumeRepresentation, gathered from the
 *          processes that drew it.
 *
 * Gather it with vtkSMSession::GatherInformation(vtkPVSession::RENDER_SERVER, info, id), id being
 * the global id of the 'PsiVolumeRepresentation' proxy: every rendering process fills it from
 * its representation (CopyFromObject), and the root adds them up (AddInformation): tetrahedra,
 * skipped cells and sort cycles are summed over the processes, times are the largest (the
 * slowest process sets the frame time). CopyFromObject can also be called directly with a local
 * representation (client-side rendering in a client/server session).
 *
 * Unlike pulling the representation's information properties, this reaches the server's
 * representation in a client/server session: ParaView pulls information properties of proxies
 * that also live on the client from the client's copy, which draws nothing when the server
 * renders.
 */
#ifndef vtkPsiFrameStatsInformation_h
#define vtkPsiFrameStatsInformation_h

#include "PsiFrameStats.h"
#include "PsiVolumeRepresentationsModule.h"
#include "vtkPVInformation.h"

class PSIVOLUMEREPRESENTATIONS_EXPORT vtkPsiFrameStatsInformation : public vtkPVInformation
{
public:
  static vtkPsiFrameStatsInformation* New();
  vtkTypeMacro(vtkPsiFrameStatsInformation, vtkPVInformation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// `object` is a vtkPsiVolumeRepresentation; anything else leaves the statistics at 0.
  void CopyFromObject(vtkObject* object) override;
  void AddInformation(vtkPVInformation* other) override;
  void CopyToStream(vtkClientServerStream* stream) override;
  void CopyFromStream(const vtkClientServerStream* stream) override;

#ifndef __VTK_WRAP__
  /// The frame gathered over the processes: counts summed, times the largest (the panel's
  /// read-out shows it).
  const psi::FrameStats& GetFrameStats() const
  {
    return this->Stats;
  }
#endif

protected:
  vtkPsiFrameStatsInformation();
  ~vtkPsiFrameStatsInformation() override;

private:
  vtkPsiFrameStatsInformation(const vtkPsiFrameStatsInformation&) = delete;
  void operator=(const vtkPsiFrameStatsInformation&) = delete;

#ifndef __VTK_WRAP__
  psi::FrameStats Stats;
#endif
};

#endif
