// PsiMeshBuffers: the tetrahedral mesh on the GPU (Maximo et al. 2010 §3.2: the mesh is uploaded
// once and each tetrahedron streamed as one point). Points (x, y, z, scalar) are a texture
// buffer the geometry shader fetches by id; each tetrahedron is one uvec4 vertex attribute of
// its four point ids; the smoothed point gradients (isosurface normals) a second texture buffer,
// uploaded only when smooth isosurfaces ask for them.
#ifndef PsiMeshBuffers_h
#define PsiMeshBuffers_h

#include "PsiTetMesh.h"

#include "vtkNew.h"
#include "vtkType.h"

#include <string>

class vtkDataArray;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkUnstructuredGridBase;
class vtkWindow;

class PsiMeshBuffers
{
public:
  PsiMeshBuffers();
  ~PsiMeshBuffers();

  /// Whether `input` colored by `scalars` (with `arrayKey` naming array, association and mode)
  /// differs from what is uploaded. Switching to an older dataset counts too (its MTime is smaller).
  bool NeedsUpdate(vtkUnstructuredGridBase* input, vtkDataArray* scalars,
    const std::string& arrayKey) const;
  /// Gathers the mesh (psi::GatherTetMesh) and uploads it. Returns false, with `error` set, when
  /// the mesh does not fit the GPU's texture-buffer limit; the mesh is then empty.
  bool Update(vtkOpenGLRenderWindow* renWin, vtkUnstructuredGridBase* input,
    vtkDataArray* scalars, bool cellScalars, const std::string& arrayKey, std::string& error);
  /// Uploads the smoothed point gradients once per mesh.
  void UpdateGradients(vtkOpenGLRenderWindow* renWin);

  /// Binds the point texture (and the gradients when `gradients`) and the tetrahedron attribute.
  void Activate(vtkShaderProgram* program, bool gradients);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* win);

  const psi::TetMesh& GetMesh() const { return this->Mesh; }
  /// Bumped at every Update: parts derived from the mesh compare it.
  int GetVersion() const { return this->Version; }

private:
  PsiMeshBuffers(const PsiMeshBuffers&) = delete;
  void operator=(const PsiMeshBuffers&) = delete;

  psi::TetMesh Mesh;
  int Version = 0;
  vtkMTimeType Time = 0;
  const void* Input = nullptr;
  std::string ArrayKey;
  vtkNew<vtkOpenGLBufferObject> PointsBuffer;
  vtkNew<vtkTextureObject> PointsTexture;
  vtkNew<vtkOpenGLBufferObject> GradientBuffer;
  vtkNew<vtkTextureObject> GradientTexture;
  bool GradientsOnGPU = false;
  bool GradientsActive = false;
  unsigned int TetBuffer = 0;
  unsigned int VAO = 0;
  bool OnGPU = false;
};

#endif
