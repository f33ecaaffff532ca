// PsiTableTextures: the lookup textures the fragment and geometry shaders read, one class per
// table, each a PsiLookupTexture (which owns the texture, binds, unbinds and releases it) with
// its own NeedsUpdate and Update from one frame's PsiTableSources and the uniforms beside its
// sampler. On the CPU side each is made from one of Core's tables (docs/architecture.md, "Words").
//  - PsiTransferFunctionTexture: the sampled transfer function (psi::TransferFunctionTable),
//    color and attenuation over the scalar range (N x 1).
//  - PsiOpacityPrefixTexture: prefix counts of non-zero opacity, for early discard (Maximo et
//    al. 2010 §3.5).
//  - PsiPartialPreIntegrationTexture: the Ψ table Psi(gamma_b, gamma_f)
//  (psi::PartialPreIntegrationTable) of
//    partial pre-integration (Moreland & Angel 2004 §4), built once per process.
//  - PsiFullPreIntegrationTexture: the 3D pre-integration table of one transfer function
//    (psi::PreIntegrationTable; Röttger, Kraus & Ertl 2000 §4), rebuilt when the sampled function
//    changes.
#ifndef PsiTableTextures_h
#define PsiTableTextures_h

#include "PsiLookupTexture.h"
#include "PsiPreIntegrationTable.h"
#include "PsiTransferFunctionTable.h"

#include "vtkType.h"

#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

class PsiTransferFunctionTexture : public PsiLookupTexture
{
public:
  PsiTransferFunctionTexture();
  /// With a separate opacity array (in.OpacityRange) the attenuation is sampled over the
  /// opacity scalars' range.
  bool NeedsUpdate(const PsiTableSources& in) const override;
  /// Samples the property; uploads (and bumps the version) only when the samples changed:
  /// ParaView touches the property's MTime for unrelated edits.
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;

  const psi::TransferFunctionTable& GetTable() const { return this->Table; }
  /// Bumped whenever the sampled content changes.
  int GetVersion() const { return this->Version; }
  /// Whether the opacity function has a zero region over the range (early discard applies).
  bool HasZeroOpacity() const { return this->ZeroOpacity; }
  /// Prefix counts of the samples with non-zero opacity (psi::OpacityPrefixCounts).
  const std::vector<float>& GetOpacityPrefix() const { return this->OpacityPrefix; }

protected:
  void SetUniforms(vtkShaderProgram* program) override;
  void Forget() override;

private:
  psi::TransferFunctionTable Table;
  std::vector<float> OpacityPrefix;
  vtkMTimeType Time = 0;
  double Range[2] = { 0, 0 };
  double OpacityRange[2] = { 0, 0 };
  int Samples = 0;
  int Version = 0;
  bool ZeroOpacity = false;
};

class PsiOpacityPrefixTexture : public PsiLookupTexture
{
public:
  PsiOpacityPrefixTexture();
  /// When the sampled transfer function (in.Transfer) changed.
  bool NeedsUpdate(const PsiTableSources& in) const override;
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;

protected:
  void SetUniforms(vtkShaderProgram* program) override;
  void Forget() override { this->Version = -1; }

private:
  int Version = -1;
  int Samples = 0;
};

class PsiPartialPreIntegrationTexture : public PsiLookupTexture
{
public:
  PsiPartialPreIntegrationTexture();
  /// Once per context: the table depends on nothing of the frame.
  bool NeedsUpdate(const PsiTableSources&) const override { return this->Size == 0; }
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;

protected:
  void SetUniforms(vtkShaderProgram* program) override;
  void Forget() override { this->Size = 0; }

private:
  int Size = 0;
};

class PsiFullPreIntegrationTexture : public PsiLookupTexture
{
public:
  PsiFullPreIntegrationTexture();
  /// When the sampled transfer function or the mesh's length axis changed.
  bool NeedsUpdate(const PsiTableSources& in) const override;
  /// Rebuilds the table for the transfer function over the length axis (segments up to its
  /// MaxLength): Röttger's table belongs to one transfer function, rebuilt on every edit.
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in) override;
  /// Seconds the last rebuild took.
  double GetLastBuildSeconds() const { return this->Table.BuildSeconds; }

protected:
  void SetUniforms(vtkShaderProgram* program) override;
  void Forget() override { this->Valid = false; }

private:
  psi::PreIntegrationTable Table; ///< its geometry; the values live on the GPU only
  int Version = -1;
  bool Valid = false;
};

/// The four lookup textures of a frame, of which a frame's plan reads some (PsiFramePlan::Tables).
struct PsiLookupTextureSet
{
  PsiTransferFunctionTexture Transfer;
  PsiOpacityPrefixTexture OpacityPrefix;
  PsiPartialPreIntegrationTexture PartialPreIntegrationTable;
  PsiFullPreIntegrationTexture PreIntegration;

  void ReleaseGraphicsResources(vtkWindow* win);
};

#endif
