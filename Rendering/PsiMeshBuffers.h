// PsiMeshBuffers: the tetrahedral mesh on the GPU (Maximo et al. 2010 §3.2: the points are
// uploaded once and each tetrahedron streamed as one point). Points (x, y, z, scalar) are a
// texture buffer the geometry shader fetches by id; the tetrahedra stay on the CPU
// (psi::TetMesh), and PsiVisibilityOrder streams them in order as uvec4 vertex attributes of their
// four point ids; the smoothed point gradients (isosurface normals) a second texture buffer,
// uploaded only when smooth isosurfaces ask for them; a separate opacity array's scalars a third
// (`opacityScalars`), only when there is one.
#ifndef PsiMeshBuffers_h
#define PsiMeshBuffers_h

#include "PsiTetMesh.h"

#include "vtkNew.h"
#include "vtkType.h"

#include <array>
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

  /// What differs between `input` colored by `scalars` (`arrayKey` naming array, association and
  /// mode) and what is uploaded: nothing, only the scalars (a new time step on the same points
  /// and cells: Maximo et al. 2010 §4 render time-varying data "without extra burden"), or the
  /// mesh. Switching to another dataset counts as a new mesh, also when its MTime is older.
  enum class Change
  {
    None,
    Scalars,
    Mesh
  };
  Change NeedsUpdate(vtkUnstructuredGridBase* input, vtkDataArray* scalars,
    const std::string& arrayKey) const;
  /// Replaces the point scalars only and re-uploads the points (not the tetrahedra); false when
  /// the mesh must be gathered again instead (see psi::UpdateTetMeshScalars).
  bool UpdateScalars(
    vtkOpenGLRenderWindow* renWin, vtkDataArray* scalars, psi::ScalarComponent component);
  /// Gathers the mesh (psi::GatherTetMesh) and uploads it. Returns false, with `error` set, when
  /// the mesh has more points than a texture buffer holds (`maxTexels`, PsiDriverLimits); the
  /// mesh is then empty.
  bool Update(vtkOpenGLRenderWindow* renWin, vtkUnstructuredGridBase* input,
    vtkDataArray* scalars, bool cellScalars, psi::ScalarComponent component,
    const std::string& arrayKey, long long maxTexels, std::string& error);
  /// Uploads `mesh`, made elsewhere (several volumes intermixed: psi::IntermixMeshes), as Update
  /// uploads a gathered one; `key` names it (GetKey).
  bool UseMesh(vtkOpenGLRenderWindow* renWin, psi::TetMesh mesh, const std::string& key,
    long long maxTexels, std::string& error);
  /// The array key of the gathered mesh, or the key given with UseMesh.
  const std::string& GetKey() const { return this->ArrayKey; }
  /// Uploads the smoothed point gradients once per mesh.
  void UpdateGradients(vtkOpenGLRenderWindow* renWin);

  /// Binds the point texture (and the gradients when `gradients`) and the vertex array.
  void Activate(vtkShaderProgram* program, bool gradients);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* win);

  const psi::TetMesh& GetMesh() const { return this->Mesh; }
  /// Bumped when points or cells change (not for new scalars): the visibility order compares it.
  int GetVersion() const { return this->Version; }

private:
  PsiMeshBuffers(const PsiMeshBuffers&) = delete;
  void operator=(const PsiMeshBuffers&) = delete;
  void UploadPoints(vtkOpenGLRenderWindow* renWin);
  bool Upload(vtkOpenGLRenderWindow* renWin, long long maxTexels, std::string& error);

  psi::TetMesh Mesh;
  int Version = 0;
  vtkMTimeType GeometryTime = 0;
  vtkMTimeType ScalarsTime = 0;
  std::array<const void*, 3> Geometry{}; // the objects holding points and cells (GeometryOf)
  std::string ArrayKey;
  vtkNew<vtkOpenGLBufferObject> PointsBuffer;
  vtkNew<vtkTextureObject> PointsTexture;
  vtkNew<vtkOpenGLBufferObject> OpacityBuffer;
  vtkNew<vtkTextureObject> OpacityTexture;
  vtkNew<vtkOpenGLBufferObject> GradientBuffer;
  vtkNew<vtkTextureObject> GradientTexture;
  bool GradientsOnGPU = false;
  bool GradientsActive = false;
  unsigned int VAO = 0;
  bool OnGPU = false;
};

#endif
