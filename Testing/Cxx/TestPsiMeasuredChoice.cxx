// The ways 'Auto' times (psi::MeasuredChoice) on a real draw: every frame of the measurement,
// whichever way it draws (front to back with 16 or 4 masks or back to front, the geometry or
// compute projector), is the image of the fixed way within 1/255 (the fan is never timed); the
// measurement ends in a choice the read-outs name; an explicit setting is honoured on every
// frame; a new mesh, a new transfer function, a new view size and a zoom measure again, new
// values on the same mesh and a small turn of the camera do not. Results only: which way wins is
// the machine's.
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPsiVolumeMapper.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace
{
constexpr int W = 160, H = 160;
constexpr int MaxFrames = 30;

struct Scene
{
  vtkNew<vtkUnstructuredGrid> Grid;
  psitest::TransferFunction TF{ 0.5 };
  vtkNew<vtkPsiVolumeMapper> Mapper;
  psitest::VolumeView View{ W, H, Mapper, TF.Property };

  Scene()
  {
    // opacity up to 0.9 per half unit across 20 units: most rays turn opaque
    psitest::MakeWaveletTets(this->Grid, 10, 1.0);
    double r[2];
    this->Grid->GetPointData()->GetScalars()->GetRange(r);
    psitest::BlueToYellow(this->TF.Color, r[0], r[1]);
    psitest::LinearOpacity(this->TF.Opacity, r[0], r[1], 0.05, 0.9);
    this->Mapper->SetInputData(this->Grid);
    psitest::LookAtCentre(this->View.Renderer, 12, 16, 34);
  }
  /// The way the last frame drew, without how it was chosen.
  std::string Way() const
  {
    const std::string& w = this->Mapper->GetLastDrawWay();
    for (const char* how : { " (as set)", " (measuring", " (chosen" })
    {
      if (w.find(how) != std::string::npos)
      {
        return w.substr(0, w.find(how));
      }
    }
    return w;
  }
  bool Measuring() const
  {
    return this->Mapper->GetLastDrawWay().find("(measuring") != std::string::npos;
  }
  void Force(psi::EarlyRayTerminations e, psi::Projectors p, psi::Decompositions d)
  {
    this->Mapper->SetEarlyRayTermination(e);
    this->Mapper->SetProjector(p);
    this->Mapper->SetDecomposition(d);
  }
};

// How many of `ways` name `what`.
size_t CountNaming(const std::set<std::string>& ways, const char* what)
{
  return std::count_if(ways.begin(), ways.end(),
    [what](const std::string& w) { return w.find(what) != std::string::npos; });
}

// Every frame until the choice is made against `fixed`, within 1/255; returns the ways drawn.
std::set<std::string> MeasureAgainst(Scene& s, const std::vector<double>& fixed, const char* name)
{
  std::set<std::string> ways;
  std::map<std::string, double> worstOf;
  double worst = 0;
  int frames = 0;
  for (; frames < MaxFrames; ++frames)
  {
    const std::vector<double> image = psitest::GrabRGB(s.View.Window);
    ways.insert(s.Way());
    const double d = psitest::LargestDifference(image, fixed);
    worstOf[s.Way()] = std::max(worstOf[s.Way()], d);
    worst = std::max(worst, d);
    if (!s.Measuring())
    {
      break;
    }
  }
  std::printf("%s: %d frames, %zu ways, largest difference %.1f/255; %s\n", name, frames + 1,
    ways.size(), 255 * worst, s.Mapper->GetLastDrawWay().c_str());
  for (const auto& w : worstOf)
  {
    PSI_CHECK(w.second <= 1.0 / 255 + 1e-9, "%s: %s drew %g/255 from the fixed way", name,
      w.first.c_str(), 255 * w.second);
  }
  PSI_CHECK(s.Mapper->GetLastDrawWay().find("(chosen by measurement of") != std::string::npos,
    "%s: a choice after %d frames: %s", name, frames + 1, s.Mapper->GetLastDrawWay().c_str());
  return ways;
}

// Every combination of the ways 'Auto' may time, each forced, against the first: within 1/255,
// whichever the order of the measurement. (Not the fan, which 'Auto' never times: it is not the
// silhouettes' image at isolated pixels, 8/255 at one pixel of this view.)
void CheckEveryWay(Scene& s, const std::vector<double>& fixed, const char* name)
{
  using ERT = psi::EarlyRayTerminations;
  for (ERT e : { ERT::Off, ERT::On })
    for (psi::Projectors p : { psi::Projectors::GeometryShader, psi::Projectors::ComputeShader })
    {
      s.Force(e, p, psi::Decompositions::Silhouette);
      const double diff = psitest::LargestDifference(psitest::GrabRGB(s.View.Window), fixed);
      PSI_CHECK(diff <= 1.0 / 255 + 1e-9, "%s: %s drew %g/255 from the fixed way", name,
        s.Mapper->GetLastDrawWay().c_str(), 255 * diff);
    }
}

void CheckEqualImages(Scene& s, const char* name)
{
  using ERT = psi::EarlyRayTerminations;
  s.Force(ERT::Off, psi::Projectors::GeometryShader, psi::Decompositions::Silhouette);
  const std::vector<double> fixed = psitest::GrabRGB(s.View.Window);
  PSI_CHECK(s.Mapper->GetLastDrawWay() == "back to front, geometry shader, silhouettes (as set)",
    "%s: forced, as set: %s", name, s.Mapper->GetLastDrawWay().c_str());
  CheckEveryWay(s, fixed, name);
  s.Force(ERT::Auto, psi::Projectors::Auto, psi::Decompositions::Auto);
  const std::set<std::string> ways = MeasureAgainst(s, fixed, name);
  // front to back (16 masks) and back to front; 4 masks when front to back stayed the faster;
  // the compute projector; never the fan
  PSI_CHECK(ways.size() >= 3u && CountNaming(ways, ", fan") == 0 &&
      ways.count("back to front, geometry shader, silhouettes") &&
      ways.count("front to back (16 masks), geometry shader, silhouettes"),
    "%s: %zu ways timed", name, ways.size());
  const std::string chosen = s.Way();
  const bool front = chosen.rfind("front to back", 0) == 0;
  PSI_CHECK(s.Mapper->GetLastUsedEarlyRayTermination() == front &&
      (s.Mapper->GetLastUsedMasksPerFrame() > 0) == front &&
      (s.Mapper->GetLastUsedProjector() == int(psi::Projectors::ComputeShader)) ==
        (chosen.find("compute") != std::string::npos) &&
      (s.Mapper->GetLastUsedDecomposition() == int(psi::Decompositions::Fan)) ==
        (chosen.find(", fan") != std::string::npos),
    "%s: the read-outs agree with %s", name, chosen.c_str());
}

// An explicit setting forces its way on every frame, while what is still 'Auto' is timed.
void CheckForced(Scene& s)
{
  using ERT = psi::EarlyRayTerminations;
  s.Force(ERT::On, psi::Projectors::ComputeShader, psi::Decompositions::Fan);
  for (int frame = 0; frame < 8; ++frame)
  {
    s.View.Window->Render();
    PSI_CHECK(s.Mapper->GetLastUsedEarlyRayTermination() &&
        s.Mapper->GetLastUsedProjector() == int(psi::Projectors::ComputeShader) &&
        s.Mapper->GetLastUsedDecomposition() == int(psi::Decompositions::Fan),
      "forced, frame %d: %s", frame, s.Mapper->GetLastDrawWay().c_str());
  }
  s.Force(ERT::Auto, psi::Projectors::Auto, psi::Decompositions::Auto);
}

// Runs frames until the choice is made; then `change` must start a new measurement (or not).
void CheckMeasuresAgain(
  Scene& s, const char* what, const std::function<void()>& change, bool again = true)
{
  for (int frame = 0; frame < MaxFrames && (frame == 0 || s.Measuring()); ++frame)
  {
    s.View.Window->Render();
  }
  change();
  s.View.Window->Render();
  PSI_CHECK(s.Measuring() == again, "%s: %s", what, s.Mapper->GetLastDrawWay().c_str());
}
} // namespace

int main()
{
  Scene s;
  CheckEqualImages(s, "perspective");
  vtkCamera* cam = s.View.Renderer->GetActiveCamera();
  cam->SetParallelProjection(1);
  cam->SetParallelScale(12);
  CheckEqualImages(s, "parallel");
  s.Mapper->SetIsosurfaceValues({ 180 });
  CheckEqualImages(s, "parallel, an isosurface");
  s.Mapper->SetIsosurfaceValues({});
  cam->SetParallelProjection(0);
  CheckForced(s);
  CheckMeasuresAgain(s, "new transfer function", [&] { s.TF.Opacity->AddPoint(150, 0.3); });
  // a time step's new values on the same mesh and range keep the choice
  CheckMeasuresAgain(
    s, "new values", [&] { s.Grid->GetPointData()->GetScalars()->Modified(); }, false);
  vtkNew<vtkUnstructuredGrid> other;
  psitest::MakeWaveletTets(other, 8, 1.0);
  CheckMeasuresAgain(s, "new mesh", [&] { s.Mapper->SetInputData(other); });
  CheckMeasuresAgain(s, "new view size", [&] { s.View.Window->SetSize(W + 40, H); });
  CheckMeasuresAgain(s, "zoom out 3x", [&] { cam->Zoom(1 / 3.0); });
  CheckMeasuresAgain(
    s, "a small turn", [&] { cam->Azimuth(5); }, false);
  return psitest::Report("TestPsiMeasuredChoice");
}
