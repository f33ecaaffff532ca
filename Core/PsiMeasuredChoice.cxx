#include "PsiMeasuredChoice.h"

#include "vtkMatrix4x4.h"

#include <algorithm>

namespace psi
{

std::string DrawWay::Describe() const
{
  std::string s = this->FrontToBack
    ? "front to back (" + std::to_string(this->MasksPerFrame) + " masks)"
    : "back to front";
  s += this->ComputeProjector ? ", compute shader" : ", geometry shader";
  return s;
}

double ProjectedFraction(
  const double b[6], const double modelToView[16], const double viewToClip[16])
{
  double modelToClip[16];
  vtkMatrix4x4::Multiply4x4(viewToClip, modelToView, modelToClip);
  double lo[2] = { 1, 1 }, hi[2] = { -1, -1 };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[4] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)],
      1 };
    double c[4];
    vtkMatrix4x4::MultiplyPoint(modelToClip, p, c);
    if (!(c[3] > 0))
    {
      return 1; // behind the eye: the box may cover the whole view
    }
    for (int k = 0; k < 2; ++k) // normalized device coordinates, -1..1 across the view
    {
      lo[k] = std::min(lo[k], std::max(-1.0, c[k] / c[3]));
      hi[k] = std::max(hi[k], std::min(1.0, c[k] / c[3]));
    }
  }
  return std::max(0.0, hi[0] - lo[0]) * std::max(0.0, hi[1] - lo[1]) / 4;
}

DrawWay MeasuredChoice::Next(const std::string& decides, double projectedPixels,
  const DrawWay& first, const DrawWayOptions& open)
{
  const double ratio = (projectedPixels + 1) / (this->MeasuredPixels + 1);
  const bool sizeChanged = ratio > ProjectedSizeRatio || ratio < 1 / ProjectedSizeRatio;
  if (!this->Started || decides != this->Decides || first != this->First || open != this->Open ||
    (open.Any() && sizeChanged))
  {
    this->Decides = decides;
    this->MeasuredPixels = projectedPixels;
    this->Open = open;
    this->Restart(first);
  }
  return this->Measuring ? this->Trial : this->Best;
}

void MeasuredChoice::Restart(const DrawWay& first)
{
  this->Started = true;
  this->First = this->Best = this->Trial = first;
  this->BestSeconds = this->TrialSeconds = std::numeric_limits<double>::infinity();
  this->TrialFrames = 0;
  this->WaysTimed = this->Open.Any() ? 1 : 0;
  this->Measuring = this->Open.Any();
  // Direction first: the mask count is tried only for a way that stays front to back.
  this->Pending.clear();
  const std::pair<bool, Dimension> dims[] = { { this->Open.Direction, Dimension::Direction },
    { this->Open.MasksPerFrame, Dimension::MasksPerFrame },
    { this->Open.Projector, Dimension::Projector } };
  for (const auto& d : dims)
  {
    if (d.first)
    {
      this->Pending.push_back(d.second);
    }
  }
}

void MeasuredChoice::Record(double seconds)
{
  if (!this->Measuring)
  {
    return;
  }
  this->TrialSeconds = std::min(this->TrialSeconds, seconds);
  if (++this->TrialFrames < FramesPerWay)
  {
    return;
  }
  if (this->TrialSeconds < this->BestSeconds) // the first way always, then any faster one
  {
    this->Best = this->Trial;
    this->BestSeconds = this->TrialSeconds;
  }
  this->TrialFrames = 0;
  this->TrialSeconds = std::numeric_limits<double>::infinity();
  this->Measuring = this->NextTrial();
}

// The next alternative: the best way so far with one more dimension switched. False when none
// is left.
bool MeasuredChoice::NextTrial()
{
  while (!this->Pending.empty())
  {
    const Dimension d = this->Pending.front();
    this->Pending.erase(this->Pending.begin());
    DrawWay w = this->Best;
    switch (d)
    {
      case Dimension::Direction:
        w.FrontToBack = !w.FrontToBack;
        break;
      case Dimension::MasksPerFrame:
        if (!w.FrontToBack)
        {
          continue; // back to front draws no mask
        }
        w.MasksPerFrame =
          w.MasksPerFrame == FewerMasksPerFrame ? DefaultMasksPerFrame : FewerMasksPerFrame;
        break;
      case Dimension::Projector:
        w.ComputeProjector = !w.ComputeProjector;
        break;
    }
    this->Trial = w;
    ++this->WaysTimed;
    return true;
  }
  return false;
}

std::string MeasuredChoice::Describe() const
{
  if (!this->Open.Any())
  {
    return "as set";
  }
  if (this->Measuring)
  {
    return "measuring (way " + std::to_string(this->WaysTimed) + ")";
  }
  return "chosen by measurement of " + std::to_string(this->WaysTimed) + " ways";
}

} // namespace psi
