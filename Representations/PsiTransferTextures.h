// PsiTransferTextures: the GPU tables the fragment and geometry shaders read, one class per
// table, each a PsiGpuTable (NeedsUpdate / Update / Activate / Deactivate from one frame's
// PsiTableSources, in the manner of VTK's vtkOpenGLVolumeLookupTable). Activate binds the texture
// and sets the uniforms the shader code of that table declares.
//  - PsiTransferFunctionTexture: color and attenuation sampled over the scalar range (N x 1).
//  - PsiOpacityPrefixTexture: prefix counts of non-zero opacity, for early discard (Maximo et
//    al. 2010 §3.5).
//  - PsiPsiTableTexture: Psi(gamma_b, gamma_f) of partial pre-integration (Moreland & Angel
//    2004 §4), built once per process.
//  - PsiPreIntegrationTexture: the full 3D pre-integration table of one transfer function
//    (Röttger, Kraus & Ertl 2000 §4), rebuilt when the sampled function changes.
#ifndef PsiTransferTextures_h
#define PsiTransferTextures_h

#include "PsiGpuTable.h"
#include "PsiPreIntegrationTable.h"
#include "PsiTransferFunctionTable.h"

#include "vtkNew.h"
#include "vtkType.h"

#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkVolumeProperty;
class vtkWindow;

class PsiTransferFunctionTexture : public PsiGpuTable
{
public:
  PsiTransferFunctionTexture();
  ~PsiTransferFunctionTexture() override;
  /// With a separate opacity array (in.OpacityRange) the attenuation is sampled over the
  /// opacity scalars' range.
  bool NeedsUpdate(const PsiTableSources& in) const override;
  /// Samples the property; uploads (and bumps the version) only when the samples changed:
  /// ParaView touches the property's MTime for unrelated edits.
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;
  void Activate(vtkShaderProgram* program) override;
  void Deactivate() override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

  const psi::TransferFunctionTable& GetTable() const { return this->Table; }
  /// Bumped whenever the sampled content changes.
  int GetVersion() const { return this->Version; }
  /// Whether the opacity function has a zero region over the range (early discard applies).
  bool HasZeroOpacity() const { return this->ZeroOpacity; }
  /// Prefix counts of the samples with non-zero opacity (psi::OpacityPrefixCounts).
  const std::vector<float>& GetOpacityPrefix() const { return this->OpacityPrefix; }

private:
  vtkNew<vtkTextureObject> Texture;
  psi::TransferFunctionTable Table;
  std::vector<float> OpacityPrefix;
  vtkMTimeType Time = 0;
  double Range[2] = { 0, 0 };
  double OpacityRange[2] = { 0, 0 };
  int Samples = 0;
  int Version = 0;
  bool ZeroOpacity = false;
};

class PsiOpacityPrefixTexture : public PsiGpuTable
{
public:
  PsiOpacityPrefixTexture();
  ~PsiOpacityPrefixTexture() override;
  /// When the sampled transfer function (in.Transfer) changed.
  bool NeedsUpdate(const PsiTableSources& in) const override;
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;
  void Activate(vtkShaderProgram* program) override;
  void Deactivate() override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

private:
  vtkNew<vtkTextureObject> Texture;
  int Version = -1;
  int Samples = 0;
};

class PsiPsiTableTexture : public PsiGpuTable
{
public:
  PsiPsiTableTexture();
  ~PsiPsiTableTexture() override;
  /// Once per context: the table depends on nothing of the frame.
  bool NeedsUpdate(const PsiTableSources&) const override { return this->Size == 0; }
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;
  void Activate(vtkShaderProgram* program) override;
  void Deactivate() override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

private:
  vtkNew<vtkTextureObject> Texture;
  int Size = 0;
};

class PsiPreIntegrationTexture : public PsiGpuTable
{
public:
  PsiPreIntegrationTexture();
  ~PsiPreIntegrationTexture() override;
  /// When the sampled transfer function or the mesh's length axis changed.
  bool NeedsUpdate(const PsiTableSources& in) const override;
  /// Rebuilds the table for the transfer function over the length axis (segments up to its
  /// MaxLength): Röttger's table belongs to one transfer function, rebuilt on every edit.
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;
  void Activate(vtkShaderProgram* program) override;
  void Deactivate() override;
  void ReleaseGraphicsResources(vtkWindow* win) override;
  /// Seconds the last rebuild took.
  double GetLastBuildSeconds() const { return this->Table.BuildSeconds; }

private:
  vtkNew<vtkTextureObject> Texture;
  psi::PreIntegrationTable Table; ///< its geometry; the values live on the GPU only
  int Version = -1;
  bool Valid = false;
};

/// The four tables of a frame, and those of them a frame's plan reads (PsiFramePlan::Tables).
struct PsiTransferTables
{
  PsiTransferFunctionTexture Transfer;
  PsiOpacityPrefixTexture OpacityPrefix;
  PsiPsiTableTexture PsiTable;
  PsiPreIntegrationTexture PreIntegration;

  void ReleaseGraphicsResources(vtkWindow* win);
};

#endif
