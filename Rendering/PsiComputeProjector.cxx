#include "PsiComputeProjector.h"

#include "PsiComputeProjectorComposer.h"
#include "PsiVisibilityOrder.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <string>
#include <vector>

namespace
{
// A vtkShaderProgram holding a compute shader (VTK 9.2's programs have vertex, fragment and
// geometry stages only), so that the mapper sets its uniforms through the same calls.
class PsiComputeProgram : public vtkShaderProgram
{
public:
  static PsiComputeProgram* New();
  vtkTypeMacro(PsiComputeProgram, vtkShaderProgram);

  bool Build(const std::string& source, std::string& error)
  {
    const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok)
    {
      error = "compute shader: " + Log(shader, false);
      glDeleteShader(shader);
      return false;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, shader);
    glLinkProgram(program);
    glDeleteShader(shader); // freed with the program
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok)
    {
      error = "compute program: " + Log(program, true);
      glDeleteProgram(program);
      return false;
    }
    this->Handle = static_cast<int>(program);
    this->Linked = true;
    return true;
  }

private:
  static std::string Log(GLuint object, bool program)
  {
    GLint n = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &n)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(static_cast<size_t>(std::max(n, 1)), '\0');
    program ? glGetProgramInfoLog(object, n, nullptr, log.data())
            : glGetShaderInfoLog(object, n, nullptr, log.data());
    return log.data();
  }
};
vtkStandardNewMacro(PsiComputeProgram);
} // namespace

PsiComputeProjector::PsiComputeProjector() = default;
PsiComputeProjector::~PsiComputeProjector() = default;

bool PsiComputeProjector::IsSupported(vtkOpenGLRenderWindow* renWin)
{
  int major = 0, minor = 0;
  renWin->GetOpenGLVersion(major, minor);
  return major > 4 || (major == 4 && minor >= 3);
}

bool PsiComputeProjector::Chosen(bool asked, vtkOpenGLRenderWindow* renWin)
{
  if (asked && !IsSupported(renWin))
  {
    vtkGenericWarningMacro(
      "Psi Volume: the compute projector needs OpenGL 4.3; using the geometry shader.");
    return false;
  }
  return asked;
}

vtkShaderProgram* PsiComputeProjector::ReadyComputeProgram(
  const psi::ShaderFeatures& f, const char* integrator, std::string& error, bool& built)
{
  const std::string key = f.Key();
  built = false;
  if (!this->Compute || key != this->Key)
  {
    // The compute shader holds the vertex and geometry code only: the features of the fragment
    // shader (the integration method, adaptive sampling) change the draw program, not it. Built
    // programs are kept by their source, as VTK's shader cache keeps the draw programs: a new
    // method reuses the compute shader (its compile is most of a new feature set's first frame
    // on llvmpipe; one view of the isosurface test draws 42 feature sets of 3 compute sources).
    const psi::ComputeProjectorSources src = psi::ComposeComputeProjector(f, integrator);
    vtkSmartPointer<vtkShaderProgram>& program = this->Built[src.Compute];
    if (!program)
    {
      vtkNew<PsiComputeProgram> fresh;
      if (!fresh->Build(src.Compute, error))
      {
        this->Built.erase(src.Compute);
        this->Compute = nullptr;
        this->Key.clear();
        return nullptr;
      }
      program = fresh.Get();
      built = true;
    }
    this->Compute = program;
    this->DrawVertex = src.Vertex;
    this->DrawFragment = src.Fragment;
    this->SlotVertices = src.SlotVertices;
    this->SlotTriangles = src.SlotTriangles;
    this->Vec4sPerVertex = src.Vec4sPerVertex;
    this->DrawProgram = nullptr;
    this->Key = key;
  }
  glUseProgram(static_cast<GLuint>(this->Compute->GetHandle()));
  return this->Compute;
}

vtkShaderProgram* PsiComputeProjector::ReadyDrawProgram(vtkOpenGLRenderWindow* renWin)
{
  this->DrawProgram = renWin->GetShaderCache()->ReadyShaderProgram(
    this->DrawVertex.c_str(), this->DrawFragment.c_str(), "");
  return this->DrawProgram;
}

void PsiComputeProjector::ReserveBuffers(size_t tetsPerPass)
{
  const size_t vec4s = tetsPerPass * this->SlotVertices * this->Vec4sPerVertex;
  const size_t indices = tetsPerPass * this->SlotTriangles * 3;
  if (vec4s == this->ReservedVec4s && indices == this->ReservedIndices)
  {
    return; // the slots of this feature set fit as they are
  }
  if (!this->Vertices)
  {
    glGenBuffers(1, &this->Vertices);
  }
  glBindBuffer(GL_ARRAY_BUFFER, this->Vertices);
  glBufferData(
    GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vec4s * 4 * sizeof(GLuint)), nullptr, GL_DYNAMIC_COPY);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  if (!this->Indices)
  {
    glGenBuffers(1, &this->Indices);
    glGenVertexArrays(1, &this->VAO);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Indices);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(indices * sizeof(GLuint)), nullptr,
    GL_DYNAMIC_COPY);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  this->ReservedVec4s = vec4s;
  this->ReservedIndices = indices;
}

bool PsiComputeProjector::Draw(vtkOpenGLRenderWindow* renWin, PsiVisibilityOrder& order,
  size_t targetPixels, long long maxBlockBytes, std::string& error,
  const std::function<void(size_t first)>& beforeChunk)
{
  const size_t vertexBytes = size_t(this->SlotVertices) * this->Vec4sPerVertex * 16;
  const size_t indexBytes = size_t(this->SlotTriangles) * 3 * sizeof(GLuint);
  // each pass's vertex and index buffers are storage blocks: within the driver's block size, in
  // whole work groups of 64 tetrahedra
  const size_t blockTets =
    static_cast<size_t>(std::max<long long>(maxBlockBytes, 0)) / std::max(vertexBytes, indexBytes);
  if (blockTets < 64)
  {
    error = "the compute projector's storage blocks would need " +
      std::to_string(64 * std::max(vertexBytes, indexBytes)) +
      " bytes per work group; this "
      "OpenGL driver allows " +
      std::to_string(maxBlockBytes) +
      " (GL_MAX_SHADER_STORAGE_BLOCK_SIZE): choose the geometry-shader projector.";
    return false;
  }
  const size_t perPass = std::min<size_t>({ PsiVisibilityOrder::MaxChunkTets,
    std::max<size_t>(64, BufferBudget / (vertexBytes + indexBytes)), blockTets / 64 * 64,
    std::max<size_t>(order.GetSize(), 1) });
  this->ReserveBuffers((perPass + 63) / 64 * 64);
  const GLuint compute = static_cast<GLuint>(this->Compute->GetHandle());
  const GLuint draw = static_cast<GLuint>(this->DrawProgram->GetHandle());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, order.GetStreamBuffer());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, this->Vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, this->Indices);
  glBindVertexArray(this->VAO);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, this->Indices);
  // The vertices reach the draw program as attributes psiVertex0.. (PsiProjectedVS.glsl).
  glBindBuffer(GL_ARRAY_BUFFER, this->Vertices);
  const GLsizei stride = static_cast<GLsizei>(this->Vec4sPerVertex * 4 * sizeof(GLuint));
  std::vector<GLuint> attributes;
  for (int t = 0; t < this->Vec4sPerVertex; ++t)
  {
    const GLint loc = glGetAttribLocation(draw, ("psiVertex" + std::to_string(t)).c_str());
    if (loc >= 0)
    {
      attributes.push_back(static_cast<GLuint>(loc));
      glEnableVertexAttribArray(static_cast<GLuint>(loc));
      glVertexAttribIPointer(static_cast<GLuint>(loc), 4, GL_UNSIGNED_INT, stride,
        reinterpret_cast<const void*>(size_t(t) * 4 * sizeof(GLuint)));
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glEnable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  const GLint firstLoc = glGetUniformLocation(compute, "firstTet");
  const GLint countLoc = glGetUniformLocation(compute, "tetCount");
  // each chunk of the order, as it is streamed, in passes that fit the buffers
  order.Draw(
    [&](size_t chunkFirst, size_t chunkCount)
    {
      for (size_t first = chunkFirst; first < chunkFirst + chunkCount; first += perPass)
      {
        const size_t n = std::min(perPass, chunkFirst + chunkCount - first);
        glUseProgram(compute);
        glUniform1ui(firstLoc, static_cast<GLuint>(first));
        glUniform1ui(countLoc, static_cast<GLuint>(n));
        glDispatchCompute(static_cast<GLuint>((n + 63) / 64), 1, 1);
        glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
        glUseProgram(draw);
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(n * this->SlotTriangles * 3),
          GL_UNSIGNED_INT, nullptr);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); // the next pass rewrites the buffers
      }
    },
    targetPixels, beforeChunk);
  glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  for (GLuint loc : attributes)
  {
    glDisableVertexAttribArray(loc); // the next feature set may lay its vertices out otherwise
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  for (GLuint b = 0; b < 4; ++b)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0);
  }
  renWin->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(0);
  return true;
}

void PsiComputeProjector::ReleaseGraphicsResources(vtkWindow* win)
{
  for (auto& built : this->Built)
  {
    built.second->ReleaseGraphicsResources(win);
  }
  this->Built.clear();
  this->Compute = nullptr;
  this->Key.clear();
  this->DrawProgram = nullptr;
  (void)win;
  if (this->Indices)
  {
    glDeleteBuffers(1, &this->Indices);
    glDeleteVertexArrays(1, &this->VAO);
  }
  if (this->Vertices)
  {
    glDeleteBuffers(1, &this->Vertices);
  }
  this->Indices = this->VAO = this->Vertices = 0;
  this->ReservedVec4s = this->ReservedIndices = 0;
}
