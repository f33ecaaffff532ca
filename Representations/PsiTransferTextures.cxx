#include "PsiTransferTextures.h"

#include "PsiTable.h"
#include "PsiTransferFunctionAnalysis.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolumeProperty.h"

namespace
{
void SetLinearClamped(vtkTextureObject* t, bool r = false)
{
  t->SetMinificationFilter(vtkTextureObject::Linear);
  t->SetMagnificationFilter(vtkTextureObject::Linear);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  if (r)
  {
    t->SetWrapR(vtkTextureObject::ClampToEdge);
  }
}

void SetUniform2(vtkShaderProgram* p, const char* name, double a, double b)
{
  const float v[2] = { static_cast<float>(a), static_cast<float>(b) };
  p->SetUniform2f(name, v);
}
} // namespace

// ---- transfer function ------------------------------------------------------------------------
PsiTransferFunctionTexture::PsiTransferFunctionTexture() = default;
PsiTransferFunctionTexture::~PsiTransferFunctionTexture() = default;

bool PsiTransferFunctionTexture::NeedsUpdate(vtkVolumeProperty* property, const double range[2],
  int samples, const double* opacityRange) const
{
  const double* orange = opacityRange ? opacityRange : range;
  return property->GetMTime() > this->Time || this->Range[0] != range[0] ||
    this->Range[1] != range[1] || this->OpacityRange[0] != orange[0] ||
    this->OpacityRange[1] != orange[1] || this->Samples != samples;
}

void PsiTransferFunctionTexture::Update(vtkOpenGLRenderWindow* renWin,
  vtkVolumeProperty* property, const double range[2], int samples, const double* opacityRange)
{
  psi::TransferFunctionTable tf =
    psi::SampleTransferFunction(property, range, samples, opacityRange);
  // the prefix also sees control points between samples, which the table may not show
  bool zero = false;
  std::vector<float> prefix = psi::OpacityPrefixCounts(tf, property, zero);
  if (tf.Rgba != this->Table.Rgba || prefix != this->OpacityPrefix || !this->Texture->GetHandle())
  {
    this->Texture->SetContext(renWin);
    this->Texture->Create1DFromRaw(tf.Size, 4, VTK_FLOAT, tf.Rgba.data());
    SetLinearClamped(this->Texture);
    this->Table = std::move(tf);
    this->OpacityPrefix = std::move(prefix);
    this->ZeroOpacity = zero;
    ++this->Version;
  }
  this->Time = property->GetMTime();
  this->Range[0] = range[0];
  this->Range[1] = range[1];
  this->OpacityRange[0] = (opacityRange ? opacityRange : range)[0];
  this->OpacityRange[1] = (opacityRange ? opacityRange : range)[1];
  this->Samples = samples;
}

void PsiTransferFunctionTexture::Activate(vtkShaderProgram* program)
{
  this->Texture->Activate();
  program->SetUniformi("transferFunction", this->Texture->GetTextureUnit());
  // texture coordinate = u * scale + shift, on texel centres, for u the scalar as a fraction of
  // the table's range (psi::TetMesh::Points4: the mesh's range is the table's); the same for a
  // separate opacity array's scalars, fractions of the attenuation's range
  const double n = this->Table.Size;
  SetUniform2(program, "tfScaleShift", (n - 1) / n, 0.5 / n);
  SetUniform2(program, "tfOpacityScaleShift", (n - 1) / n, 0.5 / n);
}

void PsiTransferFunctionTexture::Deactivate()
{
  this->Texture->Deactivate();
}

void PsiTransferFunctionTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Texture->ReleaseGraphicsResources(win);
  this->Table = psi::TransferFunctionTable();
  this->OpacityPrefix.clear();
  this->Time = 0;
}

// ---- opacity prefix counts (early discard) ----------------------------------------------------
PsiOpacityPrefixTexture::PsiOpacityPrefixTexture() = default;
PsiOpacityPrefixTexture::~PsiOpacityPrefixTexture() = default;

void PsiOpacityPrefixTexture::Update(
  vtkOpenGLRenderWindow* renWin, const PsiTransferFunctionTexture& transfer)
{
  this->Texture->SetContext(renWin);
  this->Texture->Create2DFromRaw(transfer.GetTable().Size, 1, 1, VTK_FLOAT,
    const_cast<float*>(transfer.GetOpacityPrefix().data()));
  this->Version = transfer.GetVersion();
}

void PsiOpacityPrefixTexture::Activate(
  vtkShaderProgram* program, const psi::TransferFunctionTable& table)
{
  this->Texture->Activate();
  program->SetUniformi("opacityPrefix", this->Texture->GetTextureUnit());
  // opacity scalar, a fraction u of the table's opacity range -> sample index u (N - 1)
  SetUniform2(program, "tfIndexScaleShift", table.Size - 1.0, 0.0);
  program->SetUniformi("tfSamples", table.Size);
}

void PsiOpacityPrefixTexture::Deactivate()
{
  this->Texture->Deactivate();
}

void PsiOpacityPrefixTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Texture->ReleaseGraphicsResources(win);
  this->Version = -1;
}

// ---- Psi table (partial pre-integration) ------------------------------------------------------
PsiPsiTableTexture::PsiPsiTableTexture() = default;
PsiPsiTableTexture::~PsiPsiTableTexture() = default;

void PsiPsiTableTexture::Update(vtkOpenGLRenderWindow* renWin)
{
  const psi::PsiTable& table = psi::GetDefaultPsiTable();
  this->Texture->SetContext(renWin);
  this->Texture->Create2DFromRaw(
    table.N, table.N, 1, VTK_FLOAT, const_cast<float*>(table.Values.data()));
  SetLinearClamped(this->Texture);
  this->Size = table.N;
}

void PsiPsiTableTexture::Activate(vtkShaderProgram* program)
{
  this->Texture->Activate();
  program->SetUniformi("psiTable", this->Texture->GetTextureUnit());
  SetUniform2(program, "psiScaleShift", (this->Size - 1.0) / this->Size, 0.5 / this->Size);
}

void PsiPsiTableTexture::Deactivate()
{
  this->Texture->Deactivate();
}

void PsiPsiTableTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Texture->ReleaseGraphicsResources(win);
  this->Size = 0;
}

// ---- full pre-integration (Röttger et al. 2000) -----------------------------------------------
PsiPreIntegrationTexture::PsiPreIntegrationTexture() = default;
PsiPreIntegrationTexture::~PsiPreIntegrationTexture() = default;

bool PsiPreIntegrationTexture::NeedsUpdate(
  int transferVersion, const psi::PreIntegrationLengthAxis& axis) const
{
  const psi::PreIntegrationLengthAxis& a = this->Table.Axis;
  return !this->Valid || this->Version != transferVersion || a.MaxLength != axis.MaxLength ||
    a.MinLength != axis.MinLength || a.Samples != axis.Samples;
}

double PsiPreIntegrationTexture::Update(vtkOpenGLRenderWindow* renWin,
  const PsiTransferFunctionTexture& transfer, const psi::PreIntegrationLengthAxis& axis)
{
  this->Table = psi::BuildPreIntegrationTable(transfer.GetTable(), psi::GetDefaultPsiTable(), axis);
  this->Texture->SetContext(renWin);
  this->Texture->Create3DFromRaw(this->Table.ScalarSamples, this->Table.ScalarSamples,
    this->Table.LengthSamples, 4, VTK_FLOAT, this->Table.Rgba.data());
  SetLinearClamped(this->Texture, true);
  this->Table.Rgba.clear();
  this->Table.Rgba.shrink_to_fit();
  this->Version = transfer.GetVersion();
  this->Valid = true;
  return this->Table.BuildSeconds;
}

void PsiPreIntegrationTexture::Activate(vtkShaderProgram* program)
{
  this->Texture->Activate();
  program->SetUniformi("preIntegrated", this->Texture->GetTextureUnit());
  // the scalars are fractions of the table's range (psi::TetMesh::Points4)
  const double ns = this->Table.ScalarSamples;
  SetUniform2(program, "preScalarScaleShift", (ns - 1) / ns, 0.5 / ns);
  float axis[4];
  this->Table.Axis.ShaderUniform(axis);
  program->SetUniform4f("preLengthAxis", axis);
}

void PsiPreIntegrationTexture::Deactivate()
{
  this->Texture->Deactivate();
}

void PsiPreIntegrationTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Texture->ReleaseGraphicsResources(win);
  this->Valid = false;
}

// ---- all four -----------------------------------------------------------------------------------
void PsiTransferTables::Activate(vtkShaderProgram* program, bool earlyDiscard, bool psi, bool pre)
{
  this->Transfer.Activate(program);
  if (earlyDiscard)
  {
    this->OpacityPrefix.Activate(program, this->Transfer.GetTable());
  }
  if (psi)
  {
    this->PsiTable.Activate(program);
  }
  if (pre)
  {
    this->PreIntegration.Activate(program);
  }
}

void PsiTransferTables::Deactivate(bool earlyDiscard, bool psi, bool pre)
{
  this->Transfer.Deactivate();
  if (earlyDiscard)
  {
    this->OpacityPrefix.Deactivate();
  }
  if (psi)
  {
    this->PsiTable.Deactivate();
  }
  if (pre)
  {
    this->PreIntegration.Deactivate();
  }
}

void PsiTransferTables::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Transfer.ReleaseGraphicsResources(win);
  this->OpacityPrefix.ReleaseGraphicsResources(win);
  this->PsiTable.ReleaseGraphicsResources(win);
  this->PreIntegration.ReleaseGraphicsResources(win);
}
