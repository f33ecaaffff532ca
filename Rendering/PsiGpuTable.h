// PsiGpuTable: the interface of every GPU table, what the shaders read besides the mesh: a
// lookup texture (PsiLookupTexture, which owns its texture, and the four of PsiTableTextures.h)
// or an array of uniforms (PsiAdaptiveNodes). As in VTK's vtkOpenGLVolumeLookupTable:
// NeedsUpdate and Update from one frame's sources, Activate (bind, and set the uniforms the
// table's GLSL declares), Deactivate and ReleaseGraphicsResources, with one signature for all.
// The frame plan names the tables a frame reads (PsiFramePlan::Tables), and the mapper updates,
// activates and deactivates exactly those (psi::UpdateTables, psi::ActivateTables,
// psi::DeactivateTables).
#ifndef PsiGpuTable_h
#define PsiGpuTable_h

#include "PsiPreIntegrationTable.h"
#include "PsiSettings.h" // the defaults of the table sizes
#include "PsiTransferFunctionTable.h"

#include <vector>

class PsiTransferFunctionTexture;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkVolumeProperty;
class vtkWindow;

/// What a frame's tables are made from.
struct PsiTableSources
{
  vtkVolumeProperty* Property = nullptr;
  const double* ScalarRange = nullptr;  ///< the color scalars' range: the tables' domain
  const double* OpacityRange = nullptr; ///< a separate opacity array's range; nullptr: none
  int Samples = psi::Settings().TransferFunctionSamples; ///< of the sampled transfer function
  /// The sampled transfer function the other tables derive from (updated before them).
  const PsiTransferFunctionTexture* Transfer = nullptr;
  psi::PreIntegrationLengthAxis LengthAxis; ///< the mesh's segment lengths (full pre-integration)
  int MaxNodes = psi::MaxAdaptiveNodes;     ///< adaptive sampling's node budget
  double NodeTolerance = psi::AdaptiveNodeTolerance; ///< how closely the nodes follow the function
  /// A sampled transfer function made elsewhere (several volumes intermixed: psi::IntermixTables)
  /// with its opacity prefix counts and whether it has a zero region, used instead of sampling
  /// Property; nullptr: sample Property.
  const psi::TransferFunctionTable* Table = nullptr;
  const std::vector<float>* OpacityPrefix = nullptr;
  bool ZeroOpacity = false;
};

class PsiGpuTable
{
public:
  virtual ~PsiGpuTable() = default;
  virtual bool NeedsUpdate(const PsiTableSources& in) const = 0;
  virtual void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) = 0;
  /// Binds the table (when it is a texture) and sets its uniforms on the bound `program`.
  virtual void Activate(vtkShaderProgram* program) = 0;
  virtual void Deactivate() {}
  virtual void ReleaseGraphicsResources(vtkWindow* win) = 0;
};

namespace psi
{
/// Updates each table of `tables` that needs it.
void UpdateTables(const std::vector<PsiGpuTable*>& tables, vtkOpenGLRenderWindow* renWin,
  const PsiTableSources& in);
void ActivateTables(const std::vector<PsiGpuTable*>& tables, vtkShaderProgram* program);
void DeactivateTables(const std::vector<PsiGpuTable*>& tables);
}

#endif
