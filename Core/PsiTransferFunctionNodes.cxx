#include "PsiTransferFunctionNodes.h"

#include "PsiTransferFunctionAnalysis.h"
#include "PsiTransferFunctionTable.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>

namespace psi
{
namespace
{
using Value = std::array<double, 4>; // L.r, L.g, L.b, opacity

struct Node
{
  double S;
  Value V;
};

Value Exact(vtkVolumeProperty* property, double s)
{
  Value v;
  EvaluateTransferFunction(property, s, v.data());
  v[3] = std::max(v[3], 0.0);
  return v;
}

double Distance(const Value& a, const Value& b)
{
  double d = 0;
  for (int c = 0; c < 4; ++c)
  {
    d = std::max(d, std::abs(a[c] - b[c]));
  }
  return d;
}

// The scalars of the control points of the color (or gray) and opacity functions inside range.
std::vector<double> ControlPoints(vtkVolumeProperty* property, const double range[2])
{
  std::vector<double> x;
  auto add = [&](double s)
  {
    if (s > range[0] && s < range[1])
    {
      x.push_back(s);
    }
  };
  double n[6];
  vtkPiecewiseFunction* gray =
    property->GetColorChannels(0) == 1 ? property->GetGrayTransferFunction(0) : nullptr;
  vtkColorTransferFunction* rgb = gray ? nullptr : property->GetRGBTransferFunction(0);
  for (int i = 0; gray && i < gray->GetSize(); ++i)
  {
    gray->GetNodeValue(i, n);
    add(n[0]);
  }
  for (int i = 0; rgb && i < rgb->GetSize(); ++i)
  {
    rgb->GetNodeValue(i, n);
    add(n[0]);
  }
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  for (int i = 0; opacity && i < opacity->GetSize(); ++i)
  {
    opacity->GetNodeValue(i, n);
    add(n[0]);
  }
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  return x;
}

// The range ends and the control points; a step (left and right limits apart) gives two nodes.
std::vector<Node> CornerNodes(vtkVolumeProperty* property, const double range[2])
{
  const double span = range[1] - range[0];
  const double h = 1e-12 * span; // a slope of up to 1e5 per range is not taken for a step
  std::vector<Node> nodes{ { range[0], Exact(property, range[0]) } };
  for (double x : ControlPoints(property, range))
  {
    const Value left = Exact(property, x - h), right = Exact(property, x + h);
    if (Distance(left, right) > 1e-6)
    {
      nodes.push_back({ x, left });
      nodes.push_back({ x, right });
    }
    else
    {
      nodes.push_back({ x, Exact(property, x) });
    }
  }
  if (span > 0)
  {
    nodes.push_back({ range[1], Exact(property, range[1]) });
  }
  return nodes;
}

// How far the exact function is from the chord of interval [a, b] (checked at three points).
double ChordDeviation(vtkVolumeProperty* property, const Node& a, const Node& b)
{
  double d = 0;
  for (double t : { 0.25, 0.5, 0.75 })
  {
    Value chord;
    for (int c = 0; c < 4; ++c)
    {
      chord[c] = a.V[c] + t * (b.V[c] - a.V[c]);
    }
    d = std::max(d, Distance(Exact(property, a.S + t * (b.S - a.S)), chord));
  }
  return d;
}

// Bisects the intervals farthest from their chords first, until all are within tolerance or the
// budget of nodes is spent.
std::vector<Node> Refine(vtkVolumeProperty* property, std::vector<Node> nodes, size_t maxNodes,
  double tolerance, double minWidth, double& maxDeviation)
{
  struct Gap
  {
    double Deviation;
    Node A, B;
    bool operator<(const Gap& o) const { return this->Deviation < o.Deviation; }
  };
  std::priority_queue<Gap> gaps;
  auto consider = [&](const Node& a, const Node& b)
  {
    if (b.S - a.S > minWidth)
    {
      const double d = ChordDeviation(property, a, b);
      if (d > tolerance)
      {
        gaps.push({ d, a, b });
      }
    }
  };
  for (size_t k = 0; k + 1 < nodes.size(); ++k)
  {
    consider(nodes[k], nodes[k + 1]);
  }
  std::vector<Node> added;
  while (!gaps.empty() && nodes.size() + added.size() < maxNodes)
  {
    const Gap g = gaps.top();
    gaps.pop();
    const double s = 0.5 * (g.A.S + g.B.S);
    const Node mid{ s, Exact(property, s) };
    added.push_back(mid);
    consider(g.A, mid);
    consider(mid, g.B);
  }
  maxDeviation = gaps.empty() ? 0.0 : gaps.top().Deviation; // the gaps left are above tolerance
  nodes.insert(nodes.end(), added.begin(), added.end());
  std::stable_sort(
    nodes.begin(), nodes.end(), [](const Node& x, const Node& y) { return x.S < y.S; });
  return nodes;
}
} // namespace

void TransferFunctionNodes::Lookup(double s, double out[4]) const
{
  const int n = this->Size();
  if (n == 0)
  {
    out[0] = out[1] = out[2] = out[3] = 0;
    return;
  }
  const auto j = static_cast<int>(
    std::upper_bound(this->Scalars.begin(), this->Scalars.end(), s) - this->Scalars.begin());
  const int a = std::max(j - 1, 0), b = std::min(j, n - 1);
  const double width = this->Scalars[b] - this->Scalars[a];
  const double w = width > 0 ? std::min(std::max((s - this->Scalars[a]) / width, 0.0), 1.0) : 0.0;
  for (int c = 0; c < 4; ++c)
  {
    out[c] = this->Rgba[4 * a + c] + w * (this->Rgba[4 * b + c] - this->Rgba[4 * a + c]);
  }
}

TransferFunctionNodes SampleTransferFunctionNodes(
  vtkVolumeProperty* property, const double range[2], int maxNodes, double tolerance)
{
  std::vector<Node> nodes = CornerNodes(property, range);
  const size_t budget = static_cast<size_t>(std::max(maxNodes, 2));
  if (nodes.size() > budget)
  {
    // evenly thinned, ends kept: a function this detailed is better served by the table anyway
    std::vector<Node> thin;
    for (size_t i = 0; i < budget; ++i)
    {
      thin.push_back(nodes[i * (nodes.size() - 1) / (budget - 1)]);
    }
    nodes.swap(thin);
  }
  TransferFunctionNodes out;
  nodes =
    Refine(property, nodes, budget, tolerance, 1e-6 * (range[1] - range[0]), out.MaxDeviation);
  const double unit = OpacityUnitDistance(property);
  for (const Node& n : nodes)
  {
    out.Scalars.push_back(n.S);
    for (int c = 0; c < 4; ++c)
    {
      out.Rgba.push_back(static_cast<float>(c < 3 ? n.V[c] : n.V[3] / unit));
    }
  }
  return out;
}

double TableDeviation(
  const TransferFunctionTable& table, const TransferFunctionNodes& nodes, double unitDistance)
{
  double d = 0;
  for (int k = 0; k < nodes.Size(); ++k)
  {
    double t[4];
    table.Lookup(nodes.Scalars[k], t);
    for (int c = 0; c < 4; ++c)
    {
      const double scale = c < 3 ? 1.0 : unitDistance;
      d = std::max(d, scale * std::abs(t[c] - nodes.Rgba[4 * k + c]));
    }
  }
  return d;
}
} // namespace psi
