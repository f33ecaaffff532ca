#include "PsiTableTextures.h"

#include "PsiPartialPreIntegrationTable.h"
#include "PsiTransferFunctionAnalysis.h"

#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolumeProperty.h"

namespace
{
void SetUniform2(vtkShaderProgram* p, const char* name, double a, double b)
{
  const float v[2] = { static_cast<float>(a), static_cast<float>(b) };
  p->SetUniform2f(name, v);
}
} // namespace

// ---- transfer function ------------------------------------------------------------------------
PsiTransferFunctionTexture::PsiTransferFunctionTexture()
  : PsiLookupTexture("transferFunction")
{
}

bool PsiTransferFunctionTexture::NeedsUpdate(const PsiTableSources& in) const
{
  const double* range = in.ScalarRange;
  const double* orange = in.OpacityRange ? in.OpacityRange : range;
  return in.Table || in.Property->GetMTime() > this->Time || this->Range[0] != range[0] ||
    this->Range[1] != range[1] || this->OpacityRange[0] != orange[0] ||
    this->OpacityRange[1] != orange[1] || this->Samples != in.Samples;
}

void PsiTransferFunctionTexture::Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in)
{
  vtkVolumeProperty* property = in.Property;
  const double* range = in.ScalarRange;
  const double* opacityRange = in.OpacityRange;
  psi::TransferFunctionTable tf =
    in.Table ? *in.Table : psi::SampleTransferFunction(property, range, in.Samples, opacityRange);
  // the prefix also sees control points between samples, which the table may not show
  bool zero = in.ZeroOpacity;
  std::vector<float> prefix =
    in.Table ? *in.OpacityPrefix : psi::OpacityPrefixCounts(tf, property, zero);
  if (tf.Rgba != this->Table.Rgba || prefix != this->OpacityPrefix || !this->IsUploaded())
  {
    this->TextureIn(renWin)->Create1DFromRaw(tf.Size, 4, VTK_FLOAT, tf.Rgba.data());
    this->SetLinearClamped();
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
  this->Samples = in.Samples;
}

void PsiTransferFunctionTexture::SetUniforms(vtkShaderProgram* program)
{
  // texture coordinate = u * scale + shift, on texel centres, for u the scalar as a fraction of
  // the table's range (psi::TetMesh::Points4: the mesh's range is the table's); the same for a
  // separate opacity array's scalars, fractions of the attenuation's range
  const double n = this->Table.Size;
  SetUniform2(program, "tfScaleShift", (n - 1) / n, 0.5 / n);
  SetUniform2(program, "tfOpacityScaleShift", (n - 1) / n, 0.5 / n);
}

void PsiTransferFunctionTexture::Forget()
{
  this->Table = psi::TransferFunctionTable();
  this->OpacityPrefix.clear();
  this->Time = 0;
}

// ---- opacity prefix counts (early discard) ----------------------------------------------------
PsiOpacityPrefixTexture::PsiOpacityPrefixTexture()
  : PsiLookupTexture("opacityPrefix")
{
}

bool PsiOpacityPrefixTexture::NeedsUpdate(const PsiTableSources& in) const
{
  return in.Transfer->GetVersion() != this->Version;
}

void PsiOpacityPrefixTexture::Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in)
{
  const PsiTransferFunctionTexture& transfer = *in.Transfer;
  this->Samples = transfer.GetTable().Size;
  this->TextureIn(renWin)->Create2DFromRaw(
    this->Samples, 1, 1, VTK_FLOAT, const_cast<float*>(transfer.GetOpacityPrefix().data()));
  this->Version = transfer.GetVersion();
}

void PsiOpacityPrefixTexture::SetUniforms(vtkShaderProgram* program)
{
  // opacity scalar, a fraction u of the table's opacity range -> sample index u (N - 1)
  SetUniform2(program, "tfIndexScaleShift", this->Samples - 1.0, 0.0);
  program->SetUniformi("tfSamples", this->Samples);
}

// ---- the Ψ table (partial pre-integration) ----------------------------------------------------
PsiPartialPreIntegrationTexture::PsiPartialPreIntegrationTexture()
  : PsiLookupTexture("psiTable")
{
}

void PsiPartialPreIntegrationTexture::Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources&)
{
  const psi::PartialPreIntegrationTable& table = psi::GetDefaultPsiTable();
  this->TextureIn(renWin)->Create2DFromRaw(
    table.N, table.N, 1, VTK_FLOAT, const_cast<float*>(table.Values.data()));
  this->SetLinearClamped();
  this->Size = table.N;
}

void PsiPartialPreIntegrationTexture::SetUniforms(vtkShaderProgram* program)
{
  SetUniform2(program, "psiScaleShift", (this->Size - 1.0) / this->Size, 0.5 / this->Size);
}

// ---- full pre-integration (Röttger et al. 2000) -----------------------------------------------
PsiFullPreIntegrationTexture::PsiFullPreIntegrationTexture()
  : PsiLookupTexture("preIntegrated")
{
}

bool PsiFullPreIntegrationTexture::NeedsUpdate(const PsiTableSources& in) const
{
  const psi::PreIntegrationLengthAxis& a = this->Table.Axis;
  const psi::PreIntegrationLengthAxis& axis = in.LengthAxis;
  return !this->Valid || this->Version != in.Transfer->GetVersion() ||
    a.MaxLength != axis.MaxLength || a.MinLength != axis.MinLength || a.Samples != axis.Samples;
}

void PsiFullPreIntegrationTexture::Update(vtkOpenGLRenderWindow* renWin, const PsiTableSources& in)
{
  const PsiTransferFunctionTexture& transfer = *in.Transfer;
  this->Table =
    psi::BuildPreIntegrationTable(transfer.GetTable(), psi::GetDefaultPsiTable(), in.LengthAxis);
  this->TextureIn(renWin)->Create3DFromRaw(this->Table.ScalarSamples, this->Table.ScalarSamples,
    this->Table.LengthSamples, 4, VTK_FLOAT, this->Table.Rgba.data());
  this->SetLinearClamped(true);
  this->Table.Rgba.clear();
  this->Table.Rgba.shrink_to_fit();
  this->Version = transfer.GetVersion();
  this->Valid = true;
}

void PsiFullPreIntegrationTexture::SetUniforms(vtkShaderProgram* program)
{
  // the scalars are fractions of the table's range (psi::TetMesh::Points4)
  const double ns = this->Table.ScalarSamples;
  SetUniform2(program, "preScalarScaleShift", (ns - 1) / ns, 0.5 / ns);
  float axis[4];
  this->Table.Axis.ShaderUniform(axis);
  program->SetUniform4f("preLengthAxis", axis);
}

// ---- all four ---------------------------------------------------------------------------------
void PsiLookupTextureSet::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Transfer.ReleaseGraphicsResources(win);
  this->OpacityPrefix.ReleaseGraphicsResources(win);
  this->PartialPreIntegrationTable.ReleaseGraphicsResources(win);
  this->PreIntegration.ReleaseGraphicsResources(win);
}
