//PSI::Counts::Dec
// PsiProjectCS: the compute-shader projector. One invocation projects one tetrahedron of the
// visibility order with the same code as the geometry-shader projector (Maximo et al. 2010 §3.2;
// the projection classes of Marroquim et al. 2006 §3), and writes its triangles to buffers that a
// pass-through vertex shader (PsiProjectedVS.glsl) draws in the same order. Compute shaders run on
// all of a CPU driver's threads (Mesa llvmpipe runs vertex and geometry shading on one), and on
// GPUs compute is the successor of the geometry shader.
//
// psi::ComposeComputeProjector (PsiComputeProjectorComposer.cxx) fills it with the vertex and
// geometry code composed in their function form (psi::StageForm::Functions, PsiStageInterface.h):
// psiVertexMain fills tetOut, main() copies it to tetIn[0], and psiGeometryMain sets its outputs
// (globals) and calls psiEmitVertex/psiEndPrimitive below. Each tetrahedron owns a slot of
// PSI_SLOT_VERTICES vertices (PSI_VERTEX_VEC4S uvec4 each, the bits of the clip position, then of
// the outputs) and 3 PSI_SLOT_TRIANGLES indices; the strips the geometry code emits are written as
// indexed triangles (v-2, v-1, v), so each triangle's last vertex carries its flat outputs as the
// provoking vertex of a strip would, and unused indices are the primitive-restart index.
layout(local_size_x = 64) in;

// the point ids of the tetrahedra in visibility order, as PsiVisibilityOrder streams them
layout(std430, binding = 1) readonly buffer PsiTetPoints { uvec4 tetPoints[]; };
layout(std430, binding = 2) writeonly buffer PsiProjectedVertices { uvec4 projectedVertices[]; };
layout(std430, binding = 3) writeonly buffer PsiProjectedIndices { uint projectedIndices[]; };
uniform uint firstTet; // this pass draws tetPoints[firstTet, firstTet + tetCount)
uniform uint tetCount;

uint psiSlot = 0u; // this tetrahedron's slot in this pass
int psiEmitted = 0;// vertices written to the slot
int psiStrip = 0;  // vertices of the current strip
int psiTriangles = 0;// triangles written to the slot

//PSI::Stage::Vertex

// The geometry code's end of a vertex and of a strip, defined below its outputs' declarations.
void psiEmitVertex(vec4 position);
void psiEndPrimitive();

//PSI::Stage::Geometry

// Writes vertex `v` of the pass: its clip position, then the geometry code's outputs.
void psiStoreVertex(uint v, vec4 position)
{
  uint base = v * uint(PSI_VERTEX_VEC4S);
  projectedVertices[base] = floatBitsToUint(position);
//PSI::Stage::Store
}

void psiEmitVertex(vec4 position)
{
  if (psiEmitted >= PSI_SLOT_VERTICES)
  {
    return; // beyond the slot: cannot happen within psi::GeometryOutputVertices
  }
  uint v = psiSlot * uint(PSI_SLOT_VERTICES) + uint(psiEmitted);
  psiStoreVertex(v, position);
  if (psiStrip >= 2 && psiTriangles < PSI_SLOT_TRIANGLES)
  {
    uint i = (psiSlot * uint(PSI_SLOT_TRIANGLES) + uint(psiTriangles)) * 3u;
    projectedIndices[i] = v - 2u;
    projectedIndices[i + 1u] = v - 1u;
    projectedIndices[i + 2u] = v;
    ++psiTriangles;
  }
  ++psiEmitted;
  ++psiStrip;
}

void psiEndPrimitive()
{
  psiStrip = 0;
}

void main()
{
  psiSlot = gl_GlobalInvocationID.x;
  if (psiSlot >= tetCount)
  {
    return;
  }
  psiEmitted = 0;
  psiStrip = 0;
  psiTriangles = 0;
  tetPointIds = tetPoints[firstTet + psiSlot];
  psiVertexMain();
  tetIn[0] = tetOut;
  psiGeometryMain();
  for (int t = psiTriangles; t < PSI_SLOT_TRIANGLES; ++t)
  {
    uint i = (psiSlot * uint(PSI_SLOT_TRIANGLES) + uint(t)) * 3u;
    projectedIndices[i] = 0xFFFFFFFFu; // primitive restart: no triangle
    projectedIndices[i + 1u] = 0xFFFFFFFFu;
    projectedIndices[i + 2u] = 0xFFFFFFFFu;
  }
}
