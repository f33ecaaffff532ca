// PsiStageInterface: what the projection stages hand on, and the two forms the composer writes
// them in. GL-free (plain strings).
//
// The vertex code (Shaders/PsiVolumeVS.glsl) fills `tetOut`, one tetrahedron (struct
// PsiTetrahedron); the geometry code (PsiVolumeGS.glsl) reads it as `tetIn[0]` and writes the
// per-vertex outputs the fragment shader reads (GeometryOutputs), ending each vertex with
// psiEmitVertex(position) and each strip with psiEndPrimitive(). psi::ComposeShaders writes that
// code either as a vertex and a geometry shader (StageForm::Stages: an interface block between
// them, `out` variables, EmitVertex) or as the functions psiVertexMain and psiGeometryMain of
// the compute-shader projector (StageForm::Functions: a struct and globals, which
// Shaders/PsiProjectCS.glsl stores into its buffers). Both forms come from the lists below, so
// neither is derived from the other's text.
#ifndef PsiStageInterface_h
#define PsiStageInterface_h

#include "PsiVolumeRenderingModule.h"

#include <string>
#include <vector>

namespace psi
{
struct ShaderFeatures;

enum class StageForm
{
  Stages,   ///< vertex and geometry shaders (the geometry-shader projector)
  Functions ///< psiVertexMain and psiGeometryMain of the compute-shader projector
};

/// A variable one stage hands the next: `[Qualifiers]<Type> <Name>[<Count>]`.
struct ShaderVariable
{
  std::string Qualifiers; ///< interpolation: "flat ", "smooth ", "noperspective " or empty
  std::string Type;
  std::string Name;
  int Count = 1;       ///< array length; 1: not an array
  std::string Comment; ///< what it holds, and the feature file that writes it
};

/// The members of struct PsiTetrahedron for `f`: the four view-space points, and the point ids
/// or the opacity scalars when a feature reads them.
PSIVOLUMERENDERING_EXPORT std::vector<ShaderVariable> TetrahedronMembers(const ShaderFeatures& f);
/// The geometry code's per-vertex outputs for `f`, in declaration order. The fragment shader
/// declares each as an input of the same name and qualifiers.
PSIVOLUMERENDERING_EXPORT std::vector<ShaderVariable> GeometryOutputs(const ShaderFeatures& f);
/// The shape of a GLSL type the stages hand on (float, int, uint, [iu]vec2-4, mat2-4): `Columns`
/// columns of `Size` components of `Kind` ("float", "int" or "uint").
struct TypeShape
{
  std::string Kind;
  int Size = 1;
  int Columns = 1;
};
/// The shape of `type`; throws std::logic_error for another type.
PSIVOLUMERENDERING_EXPORT TypeShape ShapeOf(const std::string& type);
/// Components of `type` (Size x Columns of ShapeOf).
PSIVOLUMERENDERING_EXPORT int Components(const std::string& type);
/// The declaration of `v` as an output of a shader stage: `[Qualifiers]out <Type> <Name>;`.
PSIVOLUMERENDERING_EXPORT std::string OutputDeclaration(const ShaderVariable& v);

/// The vertex code's declarations (its //PSI::Stage::Dec): the attribute tetPointIds and tetOut.
std::string VertexStageDeclarations(const ShaderFeatures& f, StageForm form);
/// The geometry code's declarations (its //PSI::Stage::Dec): in the Stages form the layouts,
/// tetIn[] and the outputs; in the Functions form tetIn[1] and the outputs as globals.
std::string GeometryStageDeclarations(const ShaderFeatures& f, StageForm form);
}

#endif
