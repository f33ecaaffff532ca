// psi::MeasuredChoice without a GL context: which ways it times in which order, that it keeps
// the fastest and never times a way that is not open, that what decides measures again, and
// psi::ProjectedFraction's screen coverage.
#include "PsiMeasuredChoice.h"
#include "PsiTestCheck.h"

#include <cmath>
#include <functional>
#include <map>
#include <string>

namespace
{
// Runs a measurement to its end with the frame times `cost` gives each way; returns the frames
// it took and checks that every frame drew a way the options allow.
int Measure(psi::MeasuredChoice& choice, const psi::DrawWay& first, const psi::DrawWayOptions& open,
  const std::function<double(const psi::DrawWay&)>& cost, const std::string& decides = "a",
  double pixels = 1000)
{
  int frames = 0;
  for (; frames < 100; ++frames)
  {
    const psi::DrawWay w = choice.Next(decides, pixels, first, open);
    PSI_CHECK(open.Direction || w.FrontToBack == first.FrontToBack, "direction not open");
    PSI_CHECK(open.Projector || w.ComputeProjector == first.ComputeProjector, "projector not open");
    PSI_CHECK(open.MasksPerFrame || w.MasksPerFrame == first.MasksPerFrame, "masks not open");
    if (!choice.IsMeasuring())
    {
      return frames;
    }
    choice.Record(cost(w));
  }
  return frames;
}

void TestKeepsTheFastest()
{
  psi::DrawWay first;
  first.FrontToBack = true;
  psi::DrawWayOptions all{ true, true, true };
  // back to front and the compute projector each faster: the choice has both
  auto cost = [](const psi::DrawWay& w)
  { return 1.0 - (w.FrontToBack ? 0 : 0.2) - (w.ComputeProjector ? 0.1 : 0); };
  psi::MeasuredChoice choice;
  const int frames = Measure(choice, first, all, cost);
  const psi::DrawWay best = choice.Next("a", 1000, first, all);
  PSI_CHECK(
    !best.FrontToBack && best.ComputeProjector, "kept the fastest: %s", best.Describe().c_str());
  // back to front draws no mask: that alternative is skipped
  PSI_CHECK(choice.GetWaysTimed() == 3 && frames == 3 * psi::MeasuredChoice::FramesPerWay,
    "%d ways in %d frames", choice.GetWaysTimed(), frames);
  PSI_CHECK(
    choice.Describe() == "chosen by measurement of 3 ways", "%s", choice.Describe().c_str());
  // fewer masks tried where front to back stays the faster
  auto frontFaster = [](const psi::DrawWay& w)
  { return (w.FrontToBack ? 1.0 : 2.0) - (w.MasksPerFrame == psi::FewerMasksPerFrame ? 0.1 : 0); };
  psi::MeasuredChoice masks;
  Measure(masks, first, all, frontFaster);
  PSI_CHECK(masks.GetBest().FrontToBack &&
      masks.GetBest().MasksPerFrame == psi::FewerMasksPerFrame && masks.GetWaysTimed() == 4,
    "front to back with fewer masks: %s, %d ways", masks.GetBest().Describe().c_str(),
    masks.GetWaysTimed());
  // the first way the fastest: kept; each way's time is its shortest frame
  int calls = 0;
  auto noisy = [&](const psi::DrawWay& w)
  { return (w == first ? 1.0 : 1.5) + (calls++ % 2 ? 0 : 5); };
  psi::MeasuredChoice kept;
  Measure(kept, first, all, noisy);
  PSI_CHECK(kept.GetBest() == first, "the first way kept: %s", kept.GetBest().Describe().c_str());
}

void TestNothingOpen()
{
  psi::MeasuredChoice choice;
  psi::DrawWay first;
  first.ComputeProjector = true;
  const psi::DrawWay w = choice.Next("a", 1000, first, psi::DrawWayOptions());
  PSI_CHECK(w == first && !choice.IsMeasuring() && choice.Describe() == "as set",
    "nothing open: the settings' way, nothing timed");
  choice.Record(1);
  PSI_CHECK(choice.Next("a", 1000, first, psi::DrawWayOptions()) == first, "still as set");
}

void TestMeasuresAgain()
{
  psi::DrawWay first;
  psi::DrawWayOptions open;
  open.Projector = true;
  auto computeFaster = [](const psi::DrawWay& w) { return w.ComputeProjector ? 1.0 : 2.0; };
  auto geometryFaster = [](const psi::DrawWay& w) { return w.ComputeProjector ? 2.0 : 1.0; };
  psi::MeasuredChoice choice;
  Measure(choice, first, open, computeFaster);
  PSI_CHECK(choice.Next("a", 1000, first, open).ComputeProjector, "compute chosen");
  // the camera moves, the projected size stays within a factor 2: no new measurement
  const psi::DrawWay moved = choice.Next("a", 1900, first, open);
  PSI_CHECK(moved.ComputeProjector && !choice.IsMeasuring(), "a small change of size keeps it");
  // what decides changes: measured again, and the new fastest kept
  const int frames = Measure(choice, first, open, geometryFaster, "b", 1900);
  PSI_CHECK(frames == 2 * psi::MeasuredChoice::FramesPerWay &&
      !choice.Next("b", 1900, first, open).ComputeProjector,
    "new data or transfer function: measured again (%d frames)", frames);
  // the projected size grows by more than a factor 2: measured again
  choice.Next("b", 1900 * 2.5, first, open);
  PSI_CHECK(choice.IsMeasuring() && choice.GetWaysTimed() == 1, "a zoom measures again");
  Measure(choice, first, open, computeFaster, "b", 1900 * 2.5);
  // a setting forces a way: no measurement, that way
  psi::DrawWay forced = first;
  forced.FrontToBack = true; // not the way chosen above
  PSI_CHECK(
    choice.Next("b", 4750, forced, psi::DrawWayOptions()) == forced && !choice.IsMeasuring(),
    "a forced setting is drawn as set");
}

void TestProjectedFraction()
{
  // the identity view and an orthographic clip that maps [-2, 2]^2 to the view
  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  const double ortho[16] = { 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, -0.1, 0, 0, 0, 0, 1 };
  const double half[6] = { -2, 0, -2, 2, -1, -0.5 };
  const double beyond[6] = { -10, 10, -10, 10, -1, -0.5 };
  PSI_CHECK(std::abs(psi::ProjectedFraction(half, identity, ortho) - 0.5) < 1e-12,
    "half the view: %g", psi::ProjectedFraction(half, identity, ortho));
  PSI_CHECK(psi::ProjectedFraction(beyond, identity, ortho) == 1, "clamped to the view");
  // a perspective clip (w = -z): a box behind the eye may cover everything
  const double persp[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -0.2, 0, 0, -1, 0 };
  const double far[6] = { -0.5, 0.5, -0.5, 0.5, -11, -9 };
  const double around[6] = { -0.5, 0.5, -0.5, 0.5, -1, 1 };
  const double f = psi::ProjectedFraction(far, identity, persp);
  PSI_CHECK(f > 0.0025 && f < 0.0032, "a far box covers about (1/9)^2/4: %g", f);
  PSI_CHECK(psi::ProjectedFraction(around, identity, persp) == 1, "the eye inside the box");
}
} // namespace

int main()
{
  TestKeepsTheFastest();
  TestNothingOpen();
  TestMeasuresAgain();
  TestProjectedFraction();
  return psitest::Report("TestMeasuredChoice");
}
