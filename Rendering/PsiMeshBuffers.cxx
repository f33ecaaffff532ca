#include "PsiMeshBuffers.h"

#include "PsiCellTypes.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPoints.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <sstream>

PsiMeshBuffers::PsiMeshBuffers() = default;
PsiMeshBuffers::~PsiMeshBuffers() = default;

namespace
{
// The modification time of the points and cells: for an unstructured grid those of its points,
// cells and cell types, which a new time step that shares them (ShallowCopy) leaves alone; for
// other grids the dataset's own.
vtkMTimeType GeometryTimeOf(vtkUnstructuredGridBase* input)
{
  vtkUnstructuredGrid* ug = vtkUnstructuredGrid::SafeDownCast(input);
  if (!ug || !ug->GetPoints() || !ug->GetCells() || !psi::CellTypesOf(ug))
  {
    return input->GetMTime();
  }
  return std::max(
    { ug->GetPoints()->GetMTime(), ug->GetCells()->GetMTime(), psi::CellTypesOf(ug)->GetMTime() });
}

// The objects that hold the points and cells. A new time step of the same mesh is often a new
// dataset object sharing them (ParaView's representations hand the mapper a new copy each time),
// so the dataset's own identity would re-gather the mesh and re-sort it for new scalars only.
std::array<const void*, 3> GeometryOf(vtkUnstructuredGridBase* input)
{
  vtkUnstructuredGrid* ug = vtkUnstructuredGrid::SafeDownCast(input);
  if (!ug || !ug->GetPoints() || !ug->GetCells() || !psi::CellTypesOf(ug))
  {
    return { { input, nullptr, nullptr } };
  }
  return { { ug->GetPoints(), ug->GetCells(), psi::CellTypesOf(ug) } };
}
} // namespace

PsiMeshBuffers::Change PsiMeshBuffers::NeedsUpdate(
  vtkUnstructuredGridBase* input, vtkDataArray* scalars, const std::string& arrayKey) const
{
  if (!this->Gathered || GeometryOf(input) != this->Geometry || arrayKey != this->ArrayKey ||
    GeometryTimeOf(input) != this->GeometryTime)
  {
    return Change::Mesh;
  }
  return scalars->GetMTime() != this->ScalarsTime ? Change::Scalars : Change::None;
}

bool PsiMeshBuffers::UpdateScalars(vtkDataArray* scalars, psi::ScalarComponent component)
{
  if (!psi::UpdateTetMeshScalars(this->Mesh, scalars, component))
  {
    return false;
  }
  this->ScalarsTime = scalars->GetMTime();
  this->Changed(false);
  return true;
}

// What a new mesh (`geometry`) or new scalars make stale.
void PsiMeshBuffers::Changed(bool geometry)
{
  this->Version += geometry;
  ++this->ScalarsVersion;
  this->PointsOnGPU = false;
  this->GradientsOnGPU = false;
}

void PsiMeshBuffers::UploadPoints(vtkOpenGLRenderWindow* renWin)
{
  const std::vector<float>& points4 = this->Mesh.Points4;
  this->PointsBuffer->Upload(
    points4.empty() ? std::vector<float>(4, 0.f) : points4, vtkOpenGLBufferObject::TextureBuffer);
  this->PointsTexture->SetContext(renWin);
  this->PointsTexture->CreateTextureBuffer(
    static_cast<unsigned int>(std::max<size_t>(this->Mesh.NumberOfPoints(), 1)), 4, VTK_FLOAT,
    this->PointsBuffer);
  if (!this->Mesh.Opacity.empty())
  {
    this->OpacityBuffer->Upload(this->Mesh.Opacity, vtkOpenGLBufferObject::TextureBuffer);
    this->OpacityTexture->SetContext(renWin);
    this->OpacityTexture->CreateTextureBuffer(
      static_cast<unsigned int>(this->Mesh.Opacity.size()), 1, VTK_FLOAT, this->OpacityBuffer);
  }
}

void PsiMeshBuffers::Update(vtkUnstructuredGridBase* input, vtkDataArray* scalars, bool cellScalars,
  psi::ScalarComponent component, const std::string& arrayKey)
{
  this->Mesh = psi::GatherTetMesh(input, scalars, cellScalars, component);
  this->GeometryTime = GeometryTimeOf(input);
  this->ScalarsTime = scalars->GetMTime();
  this->Geometry = GeometryOf(input);
  this->ArrayKey = arrayKey;
  this->Gathered = true;
  this->Changed(true);
}

void PsiMeshBuffers::UseMesh(psi::TetMesh mesh, const std::string& key)
{
  this->Mesh = std::move(mesh);
  this->GeometryTime = this->ScalarsTime = 0;
  this->Geometry = {};
  this->ArrayKey = key;
  this->Gathered = false;
  this->Changed(true);
}

bool PsiMeshBuffers::Upload(vtkOpenGLRenderWindow* renWin, long long maxTexels, std::string& error)
{
  if (this->PointsOnGPU)
  {
    return true;
  }
  bool fits = true;
  // one texel per point in each texture buffer (points, opacity scalars, gradients)
  if (static_cast<long long>(this->Mesh.NumberOfPoints()) > maxTexels ||
    this->Mesh.NumberOfTets() > 0xffffffffu)
  {
    std::ostringstream msg;
    msg << "the mesh has " << this->Mesh.NumberOfPoints() << " points and "
        << this->Mesh.NumberOfTets() << " tetrahedra; this OpenGL driver's texture buffers hold "
        << maxTexels << " points at most (GL_MAX_TEXTURE_BUFFER_SIZE), and at most 2^32 "
        << "tetrahedra are drawn: the mesh is not drawn.";
    error = msg.str();
    this->Mesh = psi::TetMesh();
    fits = false;
  }
  if (!this->VAO)
  {
    glGenVertexArrays(1, &this->VAO);
  }
  this->UploadPoints(renWin); // the cells reach the GPU in visibility order (PsiVisibilityOrder)
  this->PointsOnGPU = true;
  return fits;
}

void PsiMeshBuffers::UpdateGradients(vtkOpenGLRenderWindow* renWin)
{
  if (this->GradientsOnGPU)
  {
    return;
  }
  this->GradientBuffer->Upload(
    psi::PointGradients(this->Mesh), vtkOpenGLBufferObject::TextureBuffer);
  this->GradientTexture->SetContext(renWin);
  this->GradientTexture->CreateTextureBuffer(
    static_cast<unsigned int>(std::max<size_t>(this->Mesh.NumberOfPoints(), 1)), 4, VTK_FLOAT,
    this->GradientBuffer);
  this->GradientsOnGPU = true;
}

void PsiMeshBuffers::Activate(vtkShaderProgram* program, bool gradients)
{
  this->PointsTexture->Activate();
  program->SetUniformi("points", this->PointsTexture->GetTextureUnit());
  if (!this->Mesh.Opacity.empty())
  {
    this->OpacityTexture->Activate();
    program->SetUniformi("opacityScalars", this->OpacityTexture->GetTextureUnit());
  }
  this->GradientsActive = gradients && this->GradientsOnGPU;
  if (this->GradientsActive)
  {
    this->GradientTexture->Activate();
    program->SetUniformi("pointGradients", this->GradientTexture->GetTextureUnit());
  }
  glBindVertexArray(this->VAO);
}

void PsiMeshBuffers::Deactivate()
{
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  this->PointsTexture->Deactivate();
  if (!this->Mesh.Opacity.empty())
  {
    this->OpacityTexture->Deactivate();
  }
  if (this->GradientsActive)
  {
    this->GradientTexture->Deactivate();
    this->GradientsActive = false;
  }
}

void PsiMeshBuffers::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->VAO)
  {
    glDeleteVertexArrays(1, &this->VAO);
  }
  this->VAO = 0;
  this->PointsBuffer->ReleaseGraphicsResources();
  this->PointsTexture->ReleaseGraphicsResources(win);
  this->OpacityBuffer->ReleaseGraphicsResources();
  this->OpacityTexture->ReleaseGraphicsResources(win);
  this->GradientBuffer->ReleaseGraphicsResources();
  this->GradientTexture->ReleaseGraphicsResources(win);
  this->GradientsOnGPU = false;
  this->PointsOnGPU = false; // uploaded again on the next draw; the gathered mesh stays
}
