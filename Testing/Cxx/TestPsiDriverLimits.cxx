// Meshes larger than the driver's buffers (PsiDriverLimits.h), crossed with a small mesh by
// lowering the limits the mapper reads (SetDriverLimitsForTesting):
//  - the compute projector's storage blocks (GL_MAX_SHADER_STORAGE_BLOCK_SIZE): a limit that
//    holds a few work groups only draws the mesh in many passes, and the image is the one drawn
//    without the limit, which is the exact reference's; a limit below one work group draws
//    nothing and says so once, naming the limit;
//  - the points' texture buffers (GL_MAX_TEXTURE_BUFFER_SIZE): a mesh with more points draws
//    nothing, says so once naming the limit, and never draws garbage.
#include "PsiTestCheck.h"
#include "PsiTestImageCompare.h"
#include "PsiTestMeshes.h"
#include "PsiTestTransferFunction.h"
#include "PsiTestView.h"

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPsiVolumeMapper.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <string>
#include <vector>

namespace
{
constexpr int W = 160, H = 160;

// Counts the errors a mapper reports and keeps the last one's text.
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    this->Last = data ? static_cast<const char*>(data) : "";
  }
  int Count = 0;
  std::string Last;
};

double MeanDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    sum += std::abs(a[i] - b[i]);
  }
  return sum / a.size();
}

struct Scene
{
  vtkNew<vtkUnstructuredGrid> Grid;
  psitest::TransferFunction TF{ 2.0 };
  vtkNew<vtkPsiVolumeMapper> Mapper;
  vtkNew<ErrorCounter> Errors;
  psitest::VolumeView View{ W, H, Mapper, TF.Property };

  Scene()
  {
    psitest::MakeWaveletTets(this->Grid, 6, 1.0);
    double r[2];
    this->Grid->GetPointData()->GetScalars()->GetRange(r);
    psitest::BlueToYellow(this->TF.Color, r[0], r[1]);
    psitest::LinearOpacity(this->TF.Opacity, r[0], r[1], 0.05, 0.6);
    this->Mapper->SetInputData(this->Grid);
    this->Mapper->AddObserver(vtkCommand::ErrorEvent, this->Errors);
    psitest::LookAtCentre(this->View.Renderer, 10, 14, 30);
  }

  std::vector<double> Draw()
  {
    this->View.Window->Render();
    return psitest::GrabRGB(this->View.Window);
  }
};

void CheckStorageBlocks()
{
  Scene s;
  s.Mapper->SetProjector(psi::Projectors::ComputeShader);
  const std::vector<double> unlimited = s.Draw();
  const psi::ReferenceScene ref = psitest::MakeReferenceScene(s.Grid, s.TF);
  const psitest::Result exact =
    psitest::Compare("unlimited", s.View.Window, s.View.Renderer, s.View.Volume, ref, nullptr, "");
  PSI_CHECK(exact.Covered > W * H / 10 && exact.Mean < 0.01,
    "the compute projector's image against the exact reference (mean %.4f, %d covered)", exact.Mean,
    exact.Covered);
  // blocks of 96 KiB: a few work groups of 64 tetrahedra each, the mesh's 8,640 in many passes
  const long long block = 96 * 1024;
  s.Mapper->SetDriverLimitsForTesting(0, block);
  const std::vector<double> passes = s.Draw();
  std::printf("storage blocks of %lld bytes: mean difference %.6f, %d errors\n", block,
    MeanDifference(passes, unlimited), s.Errors->Count);
  PSI_CHECK(MeanDifference(passes, unlimited) < 1e-6 && s.Errors->Count == 0,
    "drawn in many passes, the same image (%.6f) and no error", MeanDifference(passes, unlimited));
  s.Mapper->SetDriverLimitsForTesting(0, 1024);
  s.Draw();
  s.View.Volume->Modified();
  s.Draw();
  PSI_CHECK(s.Errors->Count == 1 &&
      s.Errors->Last.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE") != std::string::npos,
    "below one work group: one error naming the limit (%d: %s)", s.Errors->Count,
    s.Errors->Last.c_str());
}

void CheckTextureBuffers()
{
  Scene s;
  const std::vector<double> background = [&]
  {
    s.View.Volume->VisibilityOff();
    std::vector<double> img = s.Draw();
    s.View.Volume->VisibilityOn();
    return img;
  }();
  s.Mapper->SetDriverLimitsForTesting(s.Grid->GetNumberOfPoints() - 1, 0);
  const std::vector<double> img = s.Draw();
  s.Draw();
  std::printf("texture buffers of %lld texels: %d errors, mean difference to the background "
              "%.6f\n",
    static_cast<long long>(s.Grid->GetNumberOfPoints() - 1), s.Errors->Count,
    MeanDifference(img, background));
  PSI_CHECK(
    s.Errors->Count == 1 && s.Errors->Last.find("GL_MAX_TEXTURE_BUFFER_SIZE") != std::string::npos,
    "more points than a texture buffer holds: one error naming the limit (%d: %s)", s.Errors->Count,
    s.Errors->Last.c_str());
  PSI_CHECK(MeanDifference(img, background) < 1e-6 && s.Mapper->GetNumberOfTetrahedra() == 0,
    "nothing drawn, no garbage");
}
} // namespace

int main()
{
  CheckStorageBlocks();
  CheckTextureBuffers();
  return psitest::Report("TestPsiDriverLimits");
}
