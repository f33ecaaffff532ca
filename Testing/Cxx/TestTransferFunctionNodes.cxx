// The transfer function's nodes for exact adaptive sampling (psi::TransferFunctionNodes), the
// table's deviation from them that decides 'Auto', and the early-discard prefix that must not
// drop a spike narrower than the table's sample spacing. GL-free.
#include "PsiTestCheck.h"
#include "PsiTransferFunctionAnalysis.h"
#include "PsiTransferFunctionNodes.h"
#include "PsiTransferFunctionTable.h"

#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

namespace
{
const double Range[2] = { 0.0, 1.0 };

struct Scene
{
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkVolumeProperty> Property;
  Scene()
  {
    this->Property->SetColor(this->Color);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetScalarOpacityUnitDistance(2.0);
  }
};

// Largest difference between the nodes' interpolation and the exact function over [0, 1].
double NodesError(vtkVolumeProperty* property, const psi::TransferFunctionNodes& nodes)
{
  double worst = 0;
  for (int i = 0; i <= 20000; ++i)
  {
    const double s = i / 20000.0;
    double exact[4], n[4];
    psi::EvaluateTransferFunction(property, s, exact);
    nodes.Lookup(s, n);
    n[3] *= property->GetScalarOpacityUnitDistance(0);
    for (int c = 0; c < 4; ++c)
    {
      worst = std::max(worst, std::abs(exact[c] - n[c]));
    }
  }
  return worst;
}

// A tent of opacity 1 and width w around 0.5 on white: exact as nodes for every width, missed by
// the 1024-sample table below its spacing; the early-discard prefix keeps it.
void TestSpike()
{
  for (double w : { 0.1, 0.001, 1e-4, 1e-5 })
  {
    Scene sc;
    sc.Color->AddRGBPoint(0, 1, 1, 1);
    sc.Color->AddRGBPoint(1, 1, 1, 1);
    sc.Opacity->AddPoint(0, 0);
    sc.Opacity->AddPoint(0.5 - w / 2, 0);
    sc.Opacity->AddPoint(0.5, 1);
    sc.Opacity->AddPoint(0.5 + w / 2, 0);
    sc.Opacity->AddPoint(1, 0);
    const psi::TransferFunctionNodes nodes =
      psi::SampleTransferFunctionNodes(sc.Property, Range, 64, 1.0 / 512);
    PSI_CHECK(
      nodes.Size() == 5, "w %g: %d nodes, want the 3 control points and the ends", w, nodes.Size());
    // exact up to the nodes' float positions: 2 / w * 6e-8 off near a slope of 2 / w
    PSI_CHECK(NodesError(sc.Property, nodes) < 1e-6 + 1.2e-7 / w,
      "w %g: nodes miss the function by %g", w, NodesError(sc.Property, nodes));
    double peak[4];
    nodes.Lookup(0.5, peak);
    PSI_CHECK(std::abs(peak[3] - 0.5) < 1e-6, "w %g: tau at the peak %g, want 1 / 2", w, peak[3]);
    const psi::TransferFunctionTable table = psi::SampleTransferFunction(sc.Property, Range, 1024);
    const double deviation = psi::TableDeviation(table, nodes, 2.0);
    // the table clips the peak between two samples (by 1% of it at w = 10%), and misses it below
    // its spacing
    PSI_CHECK(deviation > (w < 0.01 ? 0.5 : 1.0 / 255), "w %g: table deviation %g", w, deviation);
    bool zero = false;
    const std::vector<float> prefix = psi::OpacityPrefixCounts(table, sc.Property, zero);
    // a cell whose scalars span the spike, as the geometry shader tests it (PsiEarlyDiscardGS)
    const double x0 = (0.5 - w) * 1023, x1 = (0.5 + w) * 1023;
    const int i0 = static_cast<int>(std::floor(x0)), i1 = static_cast<int>(std::ceil(x1));
    PSI_CHECK(zero, "w %g: the opacity has zero regions", w);
    PSI_CHECK(prefix[i1] - (i0 > 0 ? prefix[i0 - 1] : 0) > 0.5,
      "w %g: a cell across the spike would be discarded", w);
    const std::vector<float> tableOnly = psi::OpacityPrefixCounts(table, nullptr, zero);
    if (w <= 1e-4)
    {
      // the table alone does not see it: the property is what keeps it
      PSI_CHECK(tableOnly[i1] - (i0 > 0 ? tableOnly[i0 - 1] : 0) < 0.5,
        "w %g: expected the table alone to miss the spike", w);
    }
  }
}

// A step (two control points at one scalar) gives two nodes there, left and right.
void TestStep()
{
  Scene sc;
  sc.Color->AddRGBPoint(0, 0, 0, 1);
  sc.Color->AddRGBPoint(1, 0, 0, 1);
  sc.Opacity->AllowDuplicateScalarsOn();
  sc.Opacity->AddPoint(0, 0.1);
  sc.Opacity->AddPoint(0.3, 0.1);
  sc.Opacity->AddPoint(0.3, 0.9);
  sc.Opacity->AddPoint(1, 0.9);
  const psi::TransferFunctionNodes nodes =
    psi::SampleTransferFunctionNodes(sc.Property, Range, 64, 1.0 / 512);
  double below[4], above[4];
  nodes.Lookup(0.3 - 1e-6, below);
  nodes.Lookup(0.3 + 1e-6, above);
  PSI_CHECK(std::abs(below[3] * 2 - 0.1) < 1e-6 && std::abs(above[3] * 2 - 0.9) < 1e-6,
    "step: %g below, %g above", below[3] * 2, above[3] * 2);
  // the range ends and the step's two sides: no refinement is needed (nor spent) around it
  PSI_CHECK(nodes.Size() == 4, "step: %d nodes, want 4", nodes.Size());
  const psi::TransferFunctionTable table = psi::SampleTransferFunction(sc.Property, Range, 1024);
  PSI_CHECK(psi::TableDeviation(table, nodes, 2.0) > 0.1, "step: the table must deviate");
}

// ParaView's default map, Cool to Warm, bends between its three nodes (Diverging space): nodes
// are added until linear interpolation is within the tolerance; within budget they stop there.
void TestBendingColorMap()
{
  Scene sc;
  sc.Color->SetColorSpaceToDiverging();
  sc.Color->AddRGBPoint(0, 0.231373, 0.298039, 0.752941);
  sc.Color->AddRGBPoint(0.5, 0.865, 0.865, 0.865);
  sc.Color->AddRGBPoint(1, 0.705882, 0.0156863, 0.14902);
  sc.Opacity->AddPoint(0, 0);
  sc.Opacity->AddPoint(1, 1);
  psi::TransferFunctionNodes corners =
    psi::SampleTransferFunctionNodes(sc.Property, Range, 3, 1.0 / 512);
  PSI_CHECK(corners.Size() == 3, "3-node budget: %d nodes", corners.Size());
  const double coarse = NodesError(sc.Property, corners);
  PSI_CHECK(coarse > 0.02, "the map bends between its nodes (%g)", coarse);
  psi::TransferFunctionNodes nodes =
    psi::SampleTransferFunctionNodes(sc.Property, Range, 64, 1.0 / 512);
  const double fine = NodesError(sc.Property, nodes);
  PSI_CHECK(fine < 1.5 / 512, "refined nodes miss the map by %g (%d nodes)", fine, nodes.Size());
  PSI_CHECK(nodes.Size() < 64, "refinement stops at the tolerance: %d nodes", nodes.Size());
  PSI_CHECK(nodes.MaxDeviation <= 1.0 / 512, "within tolerance: %g", nodes.MaxDeviation);
  PSI_CHECK(corners.MaxDeviation > 0.02, "3 nodes do not follow it: %g", corners.MaxDeviation);
  PSI_CHECK(std::is_sorted(nodes.Scalars.begin(), nodes.Scalars.end()), "nodes ascending");
  const psi::TransferFunctionTable table = psi::SampleTransferFunction(sc.Property, Range, 1024);
  PSI_CHECK(psi::TableDeviation(table, nodes, 2.0) < 1.0 / 255,
    "a smooth map is resolved by the table ('Auto' stays off): %g",
    psi::TableDeviation(table, nodes, 2.0));
}

// More bends than the budget: the nodes say they do not follow the function.
void TestOverBudget()
{
  Scene sc;
  for (int i = 0; i <= 200; ++i)
  {
    const double x = i / 200.0;
    sc.Color->AddRGBPoint(x, (i % 2) ? 1.0 : 0.0, (i % 3) ? 0.5 : 0.0, (i % 5) ? 0.2 : 0.9);
  }
  sc.Opacity->AddPoint(0, 0.5);
  sc.Opacity->AddPoint(1, 0.5);
  const psi::TransferFunctionNodes nodes =
    psi::SampleTransferFunctionNodes(sc.Property, Range, 64, 1.0 / 512);
  PSI_CHECK(nodes.Size() <= 64, "budget kept: %d nodes", nodes.Size());
  PSI_CHECK(nodes.MaxDeviation > 0.1, "201 control points in 64 nodes: deviation %g reported",
    nodes.MaxDeviation);
}
} // namespace

int main()
{
  TestOverBudget();
  TestSpike();
  TestStep();
  TestBendingColorMap();
  std::printf("%s (%d failures)\n", psitest::Failures() ? "FAILED" : "passed", psitest::Failures());
  return psitest::Failures() ? 1 : 0;
}
