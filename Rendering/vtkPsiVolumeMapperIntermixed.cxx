// vtkPsiVolumeMapper's side of several volumes in one renderer (PsiIntermixedFrames.h): every
// visible volume drawn by a vtkPsiVolumeMapper goes into one mesh and one visibility order,
// composited in one pass (Core/PsiIntermixedMesh.h), each volume with its own color map, opacity
// function (or separate opacity array) and unit distance. The call that draws a frame's
// volumes gathers each volume's mesh with its own mapper, makes the scene, and hands it to a
// mapper of its own (Union) that draws it as it would draw one input; the settings of the
// renderer's first such volume apply to the whole draw.
#include "vtkPsiVolumeMapper.h"
#include "vtkPsiVolumeMapperInternals.h"

#include "PsiIntermixedFrames.h"
#include "PsiIntermixedMesh.h"
#include "PsiSettings.h"
#include "PsiTransferFunctionAnalysis.h"
#include "PsiTransferFunctionNodes.h"

#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// The isovalues of each volume as slot scalars of the intermixed mesh (those outside the volume's
// own range dropped: they would fall into another volume's slot), with each one's opacity, and
// its color through its volume's color map.
void IntermixIsosurfaces(const std::vector<PsiIntermixedMember>& drawn,
  const std::vector<psi::IntermixedVolume>& volumes, int samples, psi::Settings& s,
  PsiIntermixedScene& scene)
{
  s.IsosurfaceValues.clear();
  s.IsosurfaceOpacities.clear();
  scene.IsoColors.clear();
  const int n = static_cast<int>(drawn.size());
  for (int k = 0; k < n; ++k)
  {
    const psi::Settings& own = drawn[k].Mapper->GetSettings();
    for (size_t i = 0; i < own.IsosurfaceValues.size(); ++i)
    {
      const double u = psi::UnitScalar(volumes[k].Mesh->ScalarRange, own.IsosurfaceValues[i]);
      if (u >= 0 && u <= 1)
      {
        s.IsosurfaceValues.push_back(psi::SlotScalar(k, n, samples, u));
        s.IsosurfaceOpacities.push_back(
          i < own.IsosurfaceOpacities.size() ? own.IsosurfaceOpacities[i] : own.IsosurfaceOpacity);
        double rgba[4];
        psi::EvaluateTransferFunction(
          drawn[k].Volume->GetProperty(), own.IsosurfaceValues[i], rgba);
        scene.IsoColors.push_back({ s.IsosurfaceValues.back(), { { rgba[0], rgba[1], rgba[2] } } });
      }
    }
  }
}

// Each volume's transfer function sampled at `samples` scalars over its own range (its separate
// opacity array's, when it has one) with its opacity prefix counts, one slot after the other; and
// its adaptive-sampling nodes, each volume within its share of the node budget.
void IntermixTransferFunctions(const std::vector<PsiIntermixedMember>& drawn,
  const std::vector<psi::IntermixedVolume>& volumes, int samples, PsiIntermixedScene& scene)
{
  std::vector<psi::TransferFunctionTable> tables;
  std::vector<std::vector<float>> prefixes;
  std::vector<psi::TransferFunctionNodes> nodes;
  std::vector<std::array<double, 2>> ranges;
  scene.ZeroOpacity = false;
  scene.TableDeviation = 0;
  const int budget = std::max(2, psi::MaxAdaptiveNodes / static_cast<int>(drawn.size()));
  for (size_t k = 0; k < drawn.size(); ++k)
  {
    const psi::TetMesh& mesh = *volumes[k].Mesh;
    vtkVolumeProperty* property = drawn[k].Volume->GetProperty();
    tables.push_back(psi::SampleTransferFunction(
      property, mesh.ScalarRange, samples, mesh.Opacity.empty() ? nullptr : mesh.OpacityRange));
    bool zero = false;
    prefixes.push_back(psi::OpacityPrefixCounts(tables.back(), property, zero));
    scene.ZeroOpacity = scene.ZeroOpacity || zero;
    nodes.push_back(psi::SampleTransferFunctionNodes(
      property, mesh.ScalarRange, budget, psi::AdaptiveNodeTolerance));
    ranges.push_back({ { mesh.ScalarRange[0], mesh.ScalarRange[1] } });
    scene.TableDeviation = std::max(scene.TableDeviation,
      psi::TableDeviation(tables.back(), nodes.back(), psi::OpacityUnitDistance(property)));
  }
  scene.Table = psi::IntermixTables(tables);
  scene.OpacityPrefix = psi::IntermixOpacityPrefixes(prefixes);
  scene.Nodes = psi::IntermixNodes(nodes, ranges, samples);
}

// The volume's matrix, row-major.
std::array<double, 16> RowMajor(vtkVolume* vol)
{
  std::array<double, 16> m;
  vtkMatrix4x4* matrix = vol->GetMatrix();
  for (int i = 0; i < 16; ++i)
  {
    m[i] = matrix->GetElement(i / 4, i % 4);
  }
  return m;
}
} // namespace

// True when this call is handled: the renderer's intermixed volumes drawn (this is the frame's
// first call) or already drawn (a later one). False: this volume is drawn on its own.
bool vtkPsiVolumeMapper::RenderIntermixed(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  const std::vector<PsiIntermixedMember> members = PsiIntermixedFrames::Members(ren);
  if (members.size() < 2)
  {
    return false;
  }
  if (!PsiIntermixedFrames::Claim(ren, this))
  {
    // drawn by the frame's first call, with the others: its read-outs, with this volume's own
    // tetrahedra, and its still frame's time (what each volume's 'Auto' interaction weighs: the
    // volumes drawn together cost together, and each chooses the level of detail as the others do)
    const vtkPsiVolumeMapper* claimant = PsiIntermixedFrames::Claimant(ren);
    this->Stats = claimant->Stats;
    this->LastStillSeconds = claimant->LastStillSeconds;
    this->CountOwnCells();
    return true;
  }
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  const psi::Settings& lead = members[0].Mapper->GetSettings();
  const int samples = lead.TransferFunctionSamples;
  // each volume's mesh, gathered by its own mapper; what its table is sampled from
  std::vector<psi::IntermixedVolume> volumes;
  std::vector<PsiIntermixedMember> drawn;
  std::ostringstream key, tablesKey;
  for (const PsiIntermixedMember& m : members)
  {
    Internals& M = *m.Mapper->Impl;
    vtkVolumeProperty* property = m.Volume->GetProperty();
    if (!psi::UnitDistanceProblem(property).empty())
    {
      continue; // as alone: no optical depth, nothing drawn (the mapper warns when alone)
    }
    if (M.Context && M.Context != renWin)
    {
      M.Release(M.Context);
    }
    M.Context = renWin;
    if (!m.Mapper->UpdateMesh(m.Volume, m.Mapper->GetInput()) ||
      M.Mesh.GetMesh().NumberOfTets() == 0)
    {
      continue;
    }
    const psi::TetMesh& mesh = M.Mesh.GetMesh();
    psi::IntermixedVolume v;
    v.Mesh = &mesh;
    v.ModelToWorld = RowMajor(m.Volume);
    volumes.push_back(v);
    drawn.push_back(m);
    key << m.Mapper << ':' << M.Mesh.GetScalarsVersion();
    for (double e : v.ModelToWorld)
    {
      key << ',' << e;
    }
    key << ';';
    tablesKey << property << ':' << property->GetMTime() << ',' << mesh.ScalarRange[0] << ','
              << mesh.ScalarRange[1] << ',' << mesh.Opacity.empty() << ',' << mesh.OpacityRange[0]
              << ',' << mesh.OpacityRange[1] << ';';
  }
  if (volumes.empty())
  {
    this->ResetStatistics();
    return true;
  }
  if (!I.Scene)
  {
    I.Scene.reset(new PsiIntermixedScene);
  }
  PsiIntermixedScene& scene = *I.Scene;
  key << "samples " << samples << " sort " << static_cast<int>(lead.SortMethod);
  if (scene.Key != key.str())
  {
    scene.Mesh = psi::IntermixMeshes(volumes, samples);
    // MPVONC's neighbours: across the faces two volumes share too
    scene.Neighbors.clear();
    if (lead.SortMethod == psi::Sorts::MPVONC)
    {
      scene.Neighbors = psi::WeldedFaceNeighbors(scene.Mesh);
    }
    scene.Key = key.str();
  }
  tablesKey << "samples " << samples;
  if (scene.TablesKey != tablesKey.str()) // sampled again only when one of them changed, as alone
  {
    IntermixTransferFunctions(drawn, volumes, samples, scene);
    scene.TablesKey = tablesKey.str();
  }

  if (!I.Union)
  {
    I.Union = vtkSmartPointer<vtkPsiVolumeMapper>::New();
    I.UnionVolume = vtkSmartPointer<vtkVolume>::New();
    I.UnionVolume->SetMapper(I.Union);
  }
  vtkPsiVolumeMapper& draw = *I.Union;
  draw.Impl->Given = &scene;
  psi::Settings settings = lead; // the first volume's, with every volume's isosurfaces
  IntermixIsosurfaces(drawn, volumes, samples, settings, scene);
  draw.SetSettings(settings);
  draw.SetLogVerbosity(this->LogVerbosity);
  I.UnionVolume->SetProperty(drawn[0].Volume->GetProperty());
  I.UnionVolume->SetPropertyKeys(vol->GetPropertyKeys()); // depth peeling's passes
  draw.Render(ren, I.UnionVolume);
  // the read-outs of the combined draw, on the mapper that drew it
  this->Stats = draw.Stats;
  this->Frame = draw.Frame;
  this->LastStillSeconds = draw.LastStillSeconds;
  this->LastUsedProjector = draw.LastUsedProjector;
  this->LastUsedEarlyDiscard = draw.LastUsedEarlyDiscard;
  this->LastUsedEarlyRayTermination = draw.LastUsedEarlyRayTermination;
  this->LastUsedDecomposition = draw.LastUsedDecomposition;
  this->LastUsedMasksPerFrame = draw.LastUsedMasksPerFrame;
  this->LastUsedNearPlaneClipping = draw.LastUsedNearPlaneClipping;
  this->LastUsedOpaqueClipping = draw.LastUsedOpaqueClipping;
  this->LastFeatureDefines = draw.LastFeatureDefines;
  this->LastUsedIsosurfaceMethod = draw.LastUsedIsosurfaceMethod;
  this->LastNumberOfAdaptiveNodes = draw.LastNumberOfAdaptiveNodes;
  this->Stats.IntermixedVolumes = static_cast<int64_t>(drawn.size());
  this->Stats.IntermixedTetrahedra = draw.Stats.NumberOfTetrahedra;
  this->CountOwnCells();
  return true;
}

// The read-outs of this volume's own cells (its mesh as its last gather left it), beside the
// combined draw's times.
void vtkPsiVolumeMapper::CountOwnCells()
{
  const psi::TetMesh& mesh = this->Impl->Mesh.GetMesh();
  this->Stats.NumberOfTetrahedra = static_cast<vtkIdType>(mesh.NumberOfTets());
  this->Stats.NumberOfSkippedCells = mesh.NonTetCells + mesh.NonFiniteTets;
}

// The scene's mesh, taken when it was made again (uploaded by UploadMesh).
void vtkPsiVolumeMapper::UpdateGivenMesh()
{
  Internals& I = *this->Impl;
  if (I.Mesh.GetKey() != I.Given->Key)
  {
    I.Mesh.UseMesh(I.Given->Mesh, I.Given->Key);
  }
}
