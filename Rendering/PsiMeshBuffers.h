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
  /// mode) and what is gathered: nothing, only the scalars (a new time step on the same points
  /// and cells: Maximo et al. 2010 §4 render time-varying data "without extra burden"), or the
  /// mesh. Switching to another dataset counts as a new mesh, also when its MTime is older.
  enum class Change
  {
    None,
    Scalars,
    Mesh
  };
  Change NeedsUpdate(
    vtkUnstructuredGridBase* input, vtkDataArray* scalars, const std::string& arrayKey) const;
  /// Replaces the point scalars only (the points are uploaded again, not the tetrahedra); false
  /// when the mesh must be gathered again instead (see psi::UpdateTetMeshScalars).
  bool UpdateScalars(vtkDataArray* scalars, psi::ScalarComponent component);
  /// Gathers the mesh (psi::GatherTetMesh). Gathered meshes reach the GPU in Upload: the
  /// volumes of an intermixed frame are gathered, and only their combined mesh is uploaded.
  void Update(vtkUnstructuredGridBase* input, vtkDataArray* scalars, bool cellScalars,
    psi::ScalarComponent component, const std::string& arrayKey);
  /// Takes `mesh`, made elsewhere (several volumes intermixed: psi::IntermixMeshes), as Update
  /// takes a gathered one; `key` names it (GetKey).
  void UseMesh(psi::TetMesh mesh, const std::string& key);
  /// Puts the mesh's points on the GPU when they changed since they were last put there (also
  /// after ReleaseGraphicsResources). Returns false, with `error` set, when the mesh has more
  /// points than a texture buffer holds (`maxTexels`, PsiDriverLimits); the mesh is then empty.
  bool Upload(vtkOpenGLRenderWindow* renWin, long long maxTexels, std::string& error);
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
  /// Bumped when the scalars change too (an intermixed frame's combined mesh compares it).
  int GetScalarsVersion() const { return this->ScalarsVersion; }

private:
  PsiMeshBuffers(const PsiMeshBuffers&) = delete;
  void operator=(const PsiMeshBuffers&) = delete;
  void UploadPoints(vtkOpenGLRenderWindow* renWin);
  void Changed(bool geometry);

  psi::TetMesh Mesh;
  int Version = 0;
  int ScalarsVersion = 0;
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
  bool Gathered = false;    ///< the mesh is Update's of the geometry and time stamps below
  bool PointsOnGPU = false; ///< the mesh's points are uploaded
};

#endif
