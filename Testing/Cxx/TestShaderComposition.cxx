// The composed Psi Volume shader programs (PsiShaderComposer.h): over a covering set of feature
// combinations (every integration method; exact / screen-linear segments; near clip; opaque
// clip; early discard; isosurfaces none / per fragment / marching tetrahedra, flat and smooth;
// adaptive sampling) each feature's code is present exactly when the feature is on, no tag is
// left, the geometry-shader budget matches max_vertices and the outputs of the composed source,
// and a representative subset compiles and links with the real driver, each stage without a
// word from the compiler (a warning such as "used uninitialized" reaches ParaView 6.1 users as a
// GL debug message at every compile). Needs an X server.
// Usage: TestShaderComposition [output-dir]   (writes the compiled subset's composed sources)
#include "PsiComputeProjector.h"
#include "PsiComputeProjectorComposer.h"
#include "PsiShaderComposer.h"
#include "PsiTestCheck.h"

#include "PsiOpenGL.h" // GLEW or glad, as the found VTK provides
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkRenderWindow.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
bool Has(const std::string& src, const char* what)
{
  return src.find(what) != std::string::npos;
}

// Lines that still look like a //PSI:: tag, or preprocessor conditionals (features are
// composed, not #ifdef'd).
int Leftovers(const std::string& src)
{
  int n = 0;
  std::istringstream in(src);
  for (std::string line; std::getline(in, line);)
  {
    const size_t b = line.find_first_not_of(" \t");
    if (b != std::string::npos &&
      (line.compare(b, 7, "//PSI::") == 0 || line.compare(b, 3, "#if") == 0))
    {
      ++n;
    }
  }
  return n;
}

// What the driver says when it compiles one stage on its own: empty for a clean compile, else
// its warnings or errors (the shader info log).
std::string CompileLog(GLenum stage, const std::string& source)
{
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(length > 1 ? static_cast<size_t>(length) : 0, '\0');
  if (length > 1)
  {
    glGetShaderInfoLog(shader, length, nullptr, &log[0]);
    log.resize(std::strlen(log.c_str()));
  }
  glDeleteShader(shader);
  return log.find_first_not_of(" \t\r\n") == std::string::npos ? std::string() : log;
}

// Fails the test when a stage of `program` (sources as VTK's shader cache completed them) or
// the compute shader `compute` draws any message from the compiler.
void CheckQuietCompile(
  vtkShaderProgram* program, const std::string& compute, const std::string& what)
{
  const std::pair<GLenum, vtkShader*> stages[] = { { GL_VERTEX_SHADER, program->GetVertexShader() },
    { GL_GEOMETRY_SHADER, program->GetGeometryShader() },
    { GL_FRAGMENT_SHADER, program->GetFragmentShader() } };
  for (const auto& stage : stages)
  {
    if (stage.second && !stage.second->GetSource().empty())
    {
      const std::string log = CompileLog(stage.first, stage.second->GetSource());
      PSI_CHECK(log.empty(), "the compiler speaks (stage 0x%x) for %s:\n%s", stage.first,
        what.c_str(), log.c_str());
    }
  }
  if (!compute.empty())
  {
    const std::string log = CompileLog(GL_COMPUTE_SHADER, compute);
    PSI_CHECK(log.empty(), "the compiler speaks (compute projector) for %s:\n%s", what.c_str(),
      log.c_str());
  }
}

// Segments: 0 the fan's screen-linear triple, 1 the fan's exact segments, 2 silhouettes (ray
// segments). Iso modes: 0 none, 1 per fragment flat, 2 per fragment smooth, 3 triangles flat,
// 4 smooth.
psi::ShaderFeatures Make(int method, int segments, bool nearClip, bool opaque, bool early, int iso,
  bool adaptive, int isoCount = 3, bool separate = false)
{
  psi::ShaderFeatures f;
  f.SeparateOpacity = separate;
  f.Method = method;
  f.ExactSegments = segments == 1;
  f.Silhouette = segments == 2;
  f.NearClip = nearClip;
  f.OpaqueClip = opaque;
  f.Adaptive = adaptive;
  f.IsoCount = iso ? isoCount : 0;
  f.IsoSmooth = iso == 2 || iso == 4;
  f.IsoTriangles = iso >= 3;
  // The mapper's rule: no early discard with per-fragment isosurfaces.
  f.EarlyDiscard = early && (iso == 0 || iso >= 3);
  return f;
}

std::string Describe(const psi::ShaderFeatures& f)
{
  return "method " + std::to_string(f.Method) + "\n" + f.Defines();
}

void CheckComposition(const psi::ShaderFeatures& f, const psi::ShaderSources& s)
{
  const std::string what = Describe(f);
  const bool iso = f.IsoCount > 0;
  const bool tri = iso && f.IsoTriangles;
  const bool perFragment = iso && !f.IsoTriangles;
  const bool exact = f.ExactSegments && !f.Silhouette, sil = f.Silhouette;
  const bool separate = f.SeparateOpacity && sil && !f.Adaptive; // the composer's rule
  const std::string& vs = s.Vertex;
  const std::string& gs = s.Geometry;
  const std::string& fs = s.Fragment;
  PSI_CHECK(
    Leftovers(vs) + Leftovers(gs) + Leftovers(fs) == 0, "tags or #if left:\n%s", what.c_str());
  // One declaration of each feature file, present exactly when the feature is on.
  struct Expect
  {
    const std::string* Src;
    const char* Text;
    bool On;
  };
  const Expect expects[] = {
    { &vs, "flat uvec4 ids;", iso || f.NearClip },
    { &gs, "flat uvec4 ids;", iso || f.NearClip },
    { &vs, "out PsiTetrahedron", true },
    { &gs, "in PsiTetrahedron", true },
    { &gs, "void main()", true },
    { &gs, "uniform int classTable[81];", true },
    { &gs, "vec3 gradient = ", exact || sil || iso },
    { &gs, "noperspective out vec3 segment;", !exact && !sil },
    { &fs, "noperspective in vec3 segment;", !exact && !sil },
    { &gs, "flat out vec4 backPlane;", exact },
    { &fs, "flat in vec4 backPlane;", exact },
    { &gs, "vec4 withEnterFlags(vec4 p0, bvec4 enters)", sil },
    { &fs, "floatBitsToUint(rayFace0) & 1u", sil },
    { &gs, "emitSilhouette();", sil },
    { &gs, "emitFan();", !sil },
    { &vs, "vec4 opacity;", separate },
    { &gs, "flat out vec4 opacityPlane;", separate },
    { &fs, "flat in vec4 opacityPlane;", separate },
    { &fs, "opacityBack = mix(opacityFront, opacityBack, toOpaque", separate && f.OpaqueClip },
    { &fs, "vec3 gO = toGradient", separate && f.NearClip },
    { &fs, "opacityFront = mix(splitOpacityFront", separate && (f.Adaptive || perFragment) },
    { &fs, "float oPiece0", separate && tri },
    { &fs, "vec2 peelDepthRange()", f.DepthPeel && sil },
    { &fs, "float oPeel0", f.DepthPeel && sil && separate },
    { &fs, "vec2 surfaceRange = peelDepthRange();", f.DepthPeel && sil && tri },
    { &gs, "uniform float nearZ;", f.NearClip },
    { &gs, "flat out ivec4 clipTet;", f.NearClip },
    { &fs, "flat in ivec4 clipTet;", f.NearClip },
    { &fs, "uniform sampler2D sceneDepth;", f.NearClip || f.OpaqueClip },
    { &fs, "float toOpaque", f.OpaqueClip },
    { &gs, "uniform sampler2D opacityPrefix;", f.EarlyDiscard },
    { &gs, "if (transparentRange(dmin, dmax))", f.EarlyDiscard && !tri },
    { &gs, "if (transparentRange(lo, hi))", f.EarlyDiscard && tri },
    { &gs, "vec3 pointNormal[4] = ", iso },
    { &gs, "uniform samplerBuffer pointGradients;", iso && f.IsoSmooth },
    { &fs, "uniform vec3 isoColors[PSI_ISO_COUNT];", iso },
    { &gs, "flat out float piece;", tri },
    { &fs, "flat in float piece;", tri },
    { &gs, "flat out mat3 isoJ;", perFragment },
    { &fs, "flat in mat3 isoJ;", perFragment },
    { &fs, "uniform float tfNodes[PSI_TF_NODES_MAX];", f.Adaptive },
    { &fs, "vec4 integrateSplit(", f.Adaptive || perFragment },
    { &fs, "uniform sampler2D psiTable;", f.Method == 1 },
    { &fs, "uniform float unitDistance;", f.Method >= 3 && f.Method <= 5 },
    { &fs, "uniform sampler3D preIntegrated;", f.Method == 6 },
  };
  for (const Expect& e : expects)
  {
    PSI_CHECK(Has(*e.Src, e.Text) == e.On, "'%s' should be %s:\n%s", e.Text,
      e.On ? "present" : "absent", what.c_str());
  }
  // Counts: the only #defines left.
  PSI_CHECK(Has(gs, "#define PSI_ISO_COUNT ") == iso && Has(fs, "#define PSI_ISO_COUNT ") == iso,
    "PSI_ISO_COUNT:\n%s", what.c_str());
  PSI_CHECK(
    Has(fs, "#define PSI_TF_NODES_MAX ") == f.Adaptive, "PSI_TF_NODES_MAX:\n%s", what.c_str());
  // The geometry-shader budget is the one declared in the source.
  std::smatch m;
  const bool found = std::regex_search(gs, m, std::regex("#define PSI_GS_MAX_VERTICES (\\d+)\n"));
  PSI_CHECK(
    found && Has(gs, "max_vertices = PSI_GS_MAX_VERTICES)"), "max_vertices:\n%s", what.c_str());
  const int vertices = psi::GeometryOutputVertices(f);
  PSI_CHECK(found && std::stoi(m[1]) == vertices, "max_vertices %s != %d:\n%s",
    found ? m[1].str().c_str() : "?", vertices, what.c_str());
  const int niso = f.IsoCount;
  const int projection = sil ? 4 : 8; // a silhouette quad; the fan's strips of 5 and 3
  PSI_CHECK(vertices == (tri ? projection * (niso + 1) + 4 * niso : projection), "vertices %d:\n%s",
    vertices, what.c_str());
  // Per-vertex components: gl_Position, the segment (the four faces' ray terms with their enter
  // flags in the low bits of p0, the scalar's two ray terms and the surface normal; frontPoint +
  // backPlane + scalarGrad; or segment), the flat data of the features (piece, clipTet, isoG0 +
  // isoJ + isoV0).
  const int components = psi::GeometryOutputComponentsPerVertex(f);
  const int expected = 4 +
    (sil        ? 19
        : exact ? 12
                : 3) +
    (separate ? 4 : 0) + (tri ? 1 : 0) + (f.NearClip ? 4 : 0) + (perFragment ? 15 : 0);
  PSI_CHECK(
    components == expected, "components %d, expected %d:\n%s", components, expected, what.c_str());
  PSI_CHECK(psi::FitsGeometryOutputLimits(f, vertices, vertices * components) &&
      !psi::FitsGeometryOutputLimits(f, vertices - 1, 1 << 30) &&
      !psi::FitsGeometryOutputLimits(f, vertices, vertices * components - 1),
    "FitsGeometryOutputLimits:\n%s", what.c_str());
}
// The function form of the compute-shader projector: the same code with no stage interface left,
// and every output of the geometry code declared once as a global.
void CheckFunctionForm(const psi::ShaderFeatures& f)
{
  const std::string what = Describe(f);
  const psi::ShaderSources s = psi::ComposeShaders(f, nullptr, psi::StageForm::Functions);
  const std::string code = s.Vertex + s.Geometry;
  PSI_CHECK(Leftovers(code) == 0, "tags or #if left in the function form:\n%s", what.c_str());
  // Built-ins and declarations of a stage: none may be left.
  static const std::regex stageOnly(
    "\\b(gl_Position|EmitVertex|EndPrimitive)\\b|void main\\(|layout\\(|"
    "#extension|//VTK::|(^|\n)[ a-z]*\\b(in|out) \\w+ \\w+(\\[\\])?;");
  std::smatch m;
  PSI_CHECK(!std::regex_search(code, m, stageOnly), "'%s' in the function form:\n%s",
    m.str().c_str(), what.c_str());
  for (const char* entry : { "void psiVertexMain()", "void psiGeometryMain()",
         "PsiTetrahedron tetIn[1];", "PsiTetrahedron tetOut;", "psiEmitVertex(" })
  {
    PSI_CHECK(Has(code, entry), "'%s' missing from the function form:\n%s", entry, what.c_str());
  }
  for (const psi::ShaderVariable& v : psi::GeometryOutputs(f))
  {
    const std::string global = "\n" + v.Type + " " + v.Name + ";";
    PSI_CHECK(Has(s.Geometry, global.c_str()) &&
        Has(s.Fragment, (" in " + v.Type + " " + v.Name + ";").c_str()),
      "output %s: a global of the geometry code, an input of the fragment shader:\n%s",
      v.Name.c_str(), what.c_str());
  }
}
// Every combination of features the composer takes: each method, segments, near clip, opaque
// clip, early discard, adaptive sampling and isosurface mode; silhouettes also with a separate
// opacity array and within depth peeling.
std::vector<psi::ShaderFeatures> AllCombinations()
{
  std::vector<psi::ShaderFeatures> all;
  for (int method = 0; method < 7; ++method)
  {
    for (int bits = 0; bits < 64; ++bits)
    {
      for (int iso = 0; iso < 5; ++iso)
      {
        const int segments = bits & 32 ? 2 : bits & 1;
        all.push_back(Make(method, segments, bits & 2, bits & 4, bits & 8, iso, bits & 16));
        if (segments == 2)
        {
          all.push_back(Make(method, 2, bits & 2, bits & 4, bits & 8, iso, bits & 16, 3, true));
          psi::ShaderFeatures peel =
            Make(method, 2, bits & 2, bits & 4, bits & 8, iso, bits & 16, 3, bits & 1);
          peel.DepthPeel = true; // within VTK's dual depth peeling
          all.push_back(peel);
        }
      }
    }
  }
  all.push_back(Make(1, false, false, false, false, 3, false, 1));
  all.push_back(Make(1, true, true, false, true, 4, true, 32));
  return all;
}

// 1. Composition of every combination (strings only): each feature's code exactly when it is
// on, one program per key and one key per program.
void CheckAllCompositions()
{
  const std::vector<psi::ShaderFeatures> all = AllCombinations();
  std::map<std::string, psi::ShaderSources> byKey;
  std::map<std::string, std::string> keyBySources;
  for (const psi::ShaderFeatures& f : all)
  {
    psi::ShaderSources s;
    try
    {
      s = psi::ComposeShaders(f);
    }
    catch (const std::exception& e)
    {
      PSI_CHECK(false, "composition throws %s:\n%s", e.what(), Describe(f).c_str());
      continue;
    }
    CheckComposition(f, s);
    CheckFunctionForm(f);
    PSI_CHECK(f == f && !(f != f), "operator==");
    const std::string key = f.Key();
    const std::string sources = s.Vertex + "\n--\n" + s.Geometry + "\n--\n" + s.Fragment;
    auto k = byKey.find(key);
    if (k != byKey.end())
    {
      PSI_CHECK(k->second.Vertex == s.Vertex && k->second.Geometry == s.Geometry &&
          k->second.Fragment == s.Fragment,
        "one key, two programs:\n%s", key.c_str());
    }
    byKey[key] = s;
    auto p = keyBySources.find(sources);
    PSI_CHECK(p == keyBySources.end() || p->second == key, "one program, two keys:\n%s\n%s",
      key.c_str(), p == keyBySources.end() ? "" : p->second.c_str());
    keyBySources[sources] = key;
  }
  // A caller's integrator source is used as given.
  {
    psi::ShaderFeatures f = Make(2, false, false, false, false, 0, false);
    const psi::ShaderSources a = psi::ComposeShaders(f, psi::IntegratorSource(0));
    const psi::ShaderSources b = psi::ComposeShaders(Make(0, false, false, false, false, 0, false));
    PSI_CHECK(a.Fragment == b.Fragment, "the integrator source argument decides the integrator");
  }
  std::printf(
    "%zu feature combinations composed, %zu distinct programs\n", all.size(), byKey.size());
}

// The fan's programs the driver compiles: every method plain and with every feature on, every
// method with each isosurface mode with and without exact segments, near and opaque clipping,
// and each feature alone.
void AddFanSubset(std::vector<psi::ShaderFeatures>& compile)
{
  for (int method = 0; method < 7; ++method)
  {
    compile.push_back(Make(method, false, false, false, false, 0, false));
    compile.push_back(Make(method, true, true, true, true, method % 2 ? 4 : 2, true));
  }
  for (int iso = 1; iso < 5; ++iso)
  {
    for (int exact = 0; exact < 2; ++exact)
    {
      for (int method = 0; method < 7; ++method)
      {
        if (method != 1)
        {
          compile.push_back(Make(method, exact, false, false, false, iso, false));
        }
      }
      compile.push_back(Make(1, exact, false, false, true, iso, false));
      compile.push_back(Make(1, exact, true, true, false, iso, iso % 2));
    }
  }
  compile.push_back(Make(1, true, false, false, false, 0, false));
  compile.push_back(Make(1, false, true, false, false, 0, false));
  compile.push_back(Make(1, false, false, true, false, 0, false));
  compile.push_back(Make(1, false, false, false, true, 0, false));
  compile.push_back(Make(1, false, false, false, false, 0, true));
  compile.push_back(Make(1, true, true, true, true, 3, true, 1));
}

// Silhouettes' programs the driver compiles (the default): every method plain and with every
// feature on, each isosurface mode with and without the other features; with a separate
// opacity array; and within depth peeling, with and without a separate opacity array.
void AddSilhouetteSubset(std::vector<psi::ShaderFeatures>& compile)
{
  for (int method = 0; method < 7; ++method)
  {
    compile.push_back(Make(method, 2, false, false, false, 0, false));
    compile.push_back(Make(method, 2, true, true, true, method % 2 ? 4 : 2, true));
  }
  for (int iso = 1; iso < 5; ++iso)
  {
    compile.push_back(Make(1, 2, false, false, false, iso, false));
    compile.push_back(Make(1, 2, true, true, true, iso, iso % 2));
  }
  // A separate opacity array: every method with every other feature on, each isosurface mode.
  for (int method = 0; method < 7; ++method)
  {
    compile.push_back(Make(method, 2, true, true, true, 0, false, 3, true));
  }
  for (int iso = 1; iso < 5; ++iso)
  {
    compile.push_back(Make(1, 2, true, true, true, iso, false, 3, true));
  }
  // Depth peeling: every method with every other feature on, each isosurface mode, with and
  // without a separate opacity array.
  for (int method = 0; method < 7; ++method)
  {
    compile.push_back(Make(method, 2, true, true, true, 0, method % 2, 3, method % 3 == 0));
    compile.back().DepthPeel = true;
  }
  for (int iso = 1; iso < 5; ++iso)
  {
    compile.push_back(Make(1, 2, true, true, true, iso, false, 3, iso % 2));
    compile.back().DepthPeel = true;
  }
}

// Writes the composed sources of program `index` (and its compute projector) to `outDir`.
void WriteSources(const std::string& outDir, int index, const psi::ShaderFeatures& f,
  const psi::ShaderSources& s, const psi::ComputeProjectorSources& c)
{
  std::ofstream(outDir + "/program" + std::to_string(index) + ".glsl")
    << "// " << Describe(f) << "\n// ---- vertex\n"
    << s.Vertex << "// ---- geometry\n"
    << s.Geometry << "// ---- fragment\n"
    << s.Fragment;
  std::ofstream(outDir + "/projector" + std::to_string(index) + ".glsl")
    << "// " << Describe(f) << "\n// ---- compute\n"
    << c.Compute << "// ---- vertex\n"
    << c.Vertex;
}

// 2. A representative subset compiled and linked by the driver, each stage without a word from
// the compiler, and the compute projector of the same features built.
void CheckDriverCompiles(const std::string& outDir)
{
  std::vector<psi::ShaderFeatures> compile;
  AddFanSubset(compile);
  AddSilhouetteSubset(compile);
  vtkNew<vtkRenderWindow> rw;
  rw->SetSize(8, 8);
  rw->SetOffScreenRendering(1);
  rw->Render();
  vtkOpenGLRenderWindow* win = vtkOpenGLRenderWindow::SafeDownCast(rw);
  PSI_CHECK(win != nullptr, "an OpenGL render window");
  int compiled = 0, computeBuilt = 0;
  PsiComputeProjector projector;
  for (const psi::ShaderFeatures& f : compile)
  {
    if (!win)
    {
      break;
    }
    const psi::ShaderSources s = psi::ComposeShaders(f);
    // The compute-shader projector of the same features: its projection pass and draw program.
    const psi::ComputeProjectorSources c = psi::ComposeComputeProjector(f);
    if (!outDir.empty())
    {
      WriteSources(outDir, compiled, f, s, c);
    }
    vtkShaderProgram* prog = win->GetShaderCache()->ReadyShaderProgram(
      s.Vertex.c_str(), s.Fragment.c_str(), s.Geometry.c_str());
    PSI_CHECK(
      prog != nullptr && prog->GetCompiled(), "does not compile or link:\n%s", Describe(f).c_str());
    compiled += prog != nullptr ? 1 : 0;
    if (prog)
    {
      CheckQuietCompile(prog, c.Compute, Describe(f));
    }
    std::string error;
    bool built = false;
    const bool project =
      projector.ReadyComputeProgram(f, psi::IntegratorSource(f.Method), error, built) != nullptr;
    PSI_CHECK(project && projector.ReadyDrawProgram(win) != nullptr,
      "the compute projector does not build: %s\n%s", error.c_str(), Describe(f).c_str());
    computeBuilt += project ? 1 : 0;
  }
  projector.ReleaseGraphicsResources(win);
  std::printf("%d of %zu programs compiled and linked, %d compute projectors", compiled,
    compile.size(), computeBuilt);
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string outDir = argc > 1 ? argv[1] : "";
  const auto t0 = std::chrono::steady_clock::now();
  CheckAllCompositions();
  CheckDriverCompiles(outDir);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(" (%.1f s)\n", seconds);
  return psitest::Report("TestShaderComposition");
}
