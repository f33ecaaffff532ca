// PsiTransferTextures: the GPU tables the fragment and geometry shaders read, one class per
// table in the manner of VTK's vtkOpenGLVolumeLookupTable (NeedsUpdate / Update / Activate /
// Deactivate). Activate binds the texture and sets the uniforms the shader code of that table
// declares.
//  - PsiTransferFunctionTexture: color and attenuation sampled over the scalar range (N x 1).
//  - PsiOpacityPrefixTexture: prefix counts of non-zero opacity, for early discard (Maximo et
//    al. 2010 §3.5).
//  - PsiPsiTableTexture: Psi(gamma_b, gamma_f) of partial pre-integration (Moreland & Angel
//    2004 §4), built once per process.
//  - PsiPreIntegrationTexture: the full 3D pre-integration table of one transfer function
//    (Röttger, Kraus & Ertl 2000 §4), rebuilt when the sampled function changes.
#ifndef PsiTransferTextures_h
#define PsiTransferTextures_h

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

class PsiTransferFunctionTexture
{
public:
  PsiTransferFunctionTexture();
  ~PsiTransferFunctionTexture();
  /// `opacityRange`: the range of a separate opacity array's scalars, over which the attenuation
  /// is sampled (nullptr: `range`, the color scalars').
  bool NeedsUpdate(vtkVolumeProperty* property, const double range[2], int samples,
    const double* opacityRange = nullptr) const;
  /// Samples the property; uploads (and bumps the version) only when the samples changed:
  /// ParaView touches the property's MTime for unrelated edits.
  void Update(vtkOpenGLRenderWindow* renWin, vtkVolumeProperty* property, const double range[2],
    int samples, const double* opacityRange = nullptr);
  void Activate(vtkShaderProgram* program);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* win);

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

class PsiOpacityPrefixTexture
{
public:
  PsiOpacityPrefixTexture();
  ~PsiOpacityPrefixTexture();
  bool NeedsUpdate(int transferVersion) const { return transferVersion != this->Version; }
  void Update(vtkOpenGLRenderWindow* renWin, const PsiTransferFunctionTexture& transfer);
  void Activate(vtkShaderProgram* program, const psi::TransferFunctionTable& table);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* win);

private:
  vtkNew<vtkTextureObject> Texture;
  int Version = -1;
};

class PsiPsiTableTexture
{
public:
  PsiPsiTableTexture();
  ~PsiPsiTableTexture();
  bool NeedsUpdate() const { return this->Size == 0; }
  void Update(vtkOpenGLRenderWindow* renWin);
  void Activate(vtkShaderProgram* program);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* win);

private:
  vtkNew<vtkTextureObject> Texture;
  int Size = 0;
};

class PsiPreIntegrationTexture
{
public:
  PsiPreIntegrationTexture();
  ~PsiPreIntegrationTexture();
  bool NeedsUpdate(int transferVersion, const psi::PreIntegrationLengthAxis& axis) const;
  /// Rebuilds the table for the transfer function over the length axis (segments up to its
  /// MaxLength); returns the seconds the build took.
  double Update(vtkOpenGLRenderWindow* renWin, const PsiTransferFunctionTexture& transfer,
    const psi::PreIntegrationLengthAxis& axis);
  void Activate(vtkShaderProgram* program);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* win);

private:
  vtkNew<vtkTextureObject> Texture;
  psi::PreIntegrationTable Table; ///< its geometry; the values live on the GPU only
  int Version = -1;
  bool Valid = false;
};

/// The four tables of a frame: binds and releases together only those its features use.
struct PsiTransferTables
{
  PsiTransferFunctionTexture Transfer;
  PsiOpacityPrefixTexture OpacityPrefix;
  PsiPsiTableTexture PsiTable;
  PsiPreIntegrationTexture PreIntegration;

  void Activate(vtkShaderProgram* program, bool earlyDiscard, bool psi, bool pre);
  void Deactivate(bool earlyDiscard, bool psi, bool pre);
  void ReleaseGraphicsResources(vtkWindow* win);
};

#endif
