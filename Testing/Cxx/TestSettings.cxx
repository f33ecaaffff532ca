// The settings declared once (Core/PsiSettingList.h, Core/PsiSettings.h), without a GL context:
//  - the table follows the list: one row per setting in order, its default the member's;
//  - the representation's XML (argv[1]) agrees with it: every setting that is a property has
//    the XML's default_values as its default, an enumeration's <Entry> values are exactly its
//    range, a boolean a BooleanDomain, a DoubleRangeDomain its range; a setting that is not a
//    property has none in the XML;
//  - the clamp: a value in range is kept with no warning; a value out of range, or not a whole
//    number for an integer, is clamped to the range with one warning naming the setting;
//  - each 'Auto' resolved in its one place.
#include "PsiSettings.h"
#include "PsiTestCheck.h"

#include "vtkNew.h"
#include "vtkPVXMLElement.h"
#include "vtkPVXMLParser.h"

#include <cmath>
#include <set>
#include <sstream>
#include <string>

namespace
{
// The representation proxy's property element named `name`, or null.
vtkPVXMLElement* FindProperty(vtkPVXMLElement* root, const std::string& name)
{
  vtkPVXMLElement* proxy = root->FindNestedElementByName("ProxyGroup");
  proxy = proxy ? proxy->FindNestedElementByName("RepresentationProxy") : nullptr;
  for (unsigned i = 0; proxy && i < proxy->GetNumberOfNestedElements(); ++i)
  {
    vtkPVXMLElement* e = proxy->GetNestedElement(i);
    const char* n = e->GetAttribute("name");
    if (n && name == n && std::string(e->GetName()).find("VectorProperty") != std::string::npos)
    {
      return e;
    }
  }
  return nullptr;
}

double Attribute(vtkPVXMLElement* e, const char* name)
{
  const char* v = e ? e->GetAttribute(name) : nullptr;
  return v ? std::stod(v) : std::nan("");
}

// The value of setting `info` in a default-constructed struct of its kind.
double DefaultOf(const psi::SettingInfo& info)
{
  return info.Interaction ? psi::ValueOf(psi::InteractionSettings(), info.Id)
                          : psi::ValueOf(psi::Settings(), info.Id);
}

void CheckXML(vtkPVXMLElement* root)
{
  for (const psi::SettingInfo& info : psi::SettingTable())
  {
    PSI_CHECK(info.Default == DefaultOf(info), "%s: the table's default %g, the member's %g",
      info.Name, info.Default, DefaultOf(info));
    vtkPVXMLElement* prop = FindProperty(root, info.Name);
    PSI_CHECK((prop != nullptr) == info.Property, "%s: a property in the XML %s", info.Name,
      info.Property ? "is missing" : "that the list says is the mapper's only");
    if (!prop)
    {
      continue;
    }
    const double xml = Attribute(prop, "default_values");
    PSI_CHECK(
      xml == info.Default, "%s: XML default %g, settings default %g", info.Name, xml, info.Default);
    PSI_CHECK((prop->FindNestedElementByName("BooleanDomain") != nullptr) ==
        (info.Kind == psi::SettingKind::Boolean),
      "%s: a BooleanDomain exactly for a boolean", info.Name);
    if (vtkPVXMLElement* domain = prop->FindNestedElementByName("EnumerationDomain"))
    {
      std::set<double> entries, range;
      for (unsigned i = 0; i < domain->GetNumberOfNestedElements(); ++i)
      {
        entries.insert(Attribute(domain->GetNestedElement(i), "value"));
      }
      for (int v = static_cast<int>(info.Min); v <= static_cast<int>(info.Max); ++v)
      {
        range.insert(v);
      }
      PSI_CHECK(info.Kind == psi::SettingKind::Enumeration && entries == range,
        "%s: the XML's entries are not the values %g to %g", info.Name, info.Min, info.Max);
    }
    else
    {
      PSI_CHECK(info.Kind != psi::SettingKind::Enumeration, "%s: an enumeration without entries",
        info.Name);
    }
    if (vtkPVXMLElement* domain = prop->FindNestedElementByName("DoubleRangeDomain"))
    {
      PSI_CHECK(Attribute(domain, "min") == info.Min, "%s: XML min", info.Name);
      const double max = Attribute(domain, "max");
      PSI_CHECK(
        std::isnan(max) || max == info.Max, "%s: XML max %g, range %g", info.Name, max, info.Max);
    }
  }
}

// The clamp of one setting in the struct of its kind.
template <typename Struct>
void CheckClampOf(const psi::SettingInfo& info)
{
  Struct s;
  PSI_CHECK(psi::SetClamped(s, info.Id, info.Max).empty(), "%s: its maximum is valid", info.Name);
  PSI_CHECK(psi::SetClamped(s, info.Id, info.Min).empty(), "%s: its minimum is valid", info.Name);
  const std::string high = psi::SetClamped(s, info.Id, info.Max + 7);
  PSI_CHECK(psi::ValueOf(s, info.Id) == info.Max && high.find(info.Name) != std::string::npos,
    "%s: above its range: %g used, warning '%s'", info.Name, psi::ValueOf(s, info.Id),
    high.c_str());
  const std::string low = psi::SetClamped(s, info.Id, info.Min - 1);
  PSI_CHECK(psi::ValueOf(s, info.Id) == info.Min && !low.empty(), "%s: below its range", info.Name);
  PSI_CHECK(
    !psi::SetClamped(s, info.Id, std::nan("")).empty() && psi::ValueOf(s, info.Id) == info.Min,
    "%s: NaN", info.Name);
}

void CheckClamp()
{
  for (const psi::SettingInfo& info : psi::SettingTable())
  {
    if (info.Interaction)
    {
      CheckClampOf<psi::InteractionSettings>(info);
      psi::Settings other;
      PSI_CHECK(!psi::SetClamped(other, info.Id, info.Min).empty() &&
          std::isnan(psi::ValueOf(other, info.Id)),
        "%s: not a setting of the mapper's struct", info.Name);
    }
    else
    {
      CheckClampOf<psi::Settings>(info);
    }
  }
  psi::Settings s;
  const std::string w = psi::SetClamped(s, psi::Setting::Projector, 7);
  PSI_CHECK(w == "'Psi Volume' Projector = 7 is not one of its values (0 to 2): 2 is used.",
    "the warning reads '%s'", w.c_str());
  PSI_CHECK(!psi::SetClamped(s, psi::Setting::SortMethod, 0.5).empty() &&
      s.SortMethod == psi::Sorts::Centroid,
    "an integer setting given a fraction");
  // what a setter learns: whether to warn, and whether to mark itself modified
  psi::InteractionSettings interaction;
  psi::SettingChange c = psi::Change(interaction, psi::Setting::InteractiveBudget, 0.1);
  PSI_CHECK(!c.Changed && c.Warning.empty(), "the default set again: no change, no warning");
  c = psi::Change(interaction, psi::Setting::InteractiveBudget, 100);
  PSI_CHECK(c.Changed && !c.Warning.empty() && interaction.InteractiveBudget == 60,
    "out of range: clamped, changed, warned");
  c = psi::Change(interaction, psi::Setting::InteractiveBudget, 100);
  PSI_CHECK(!c.Changed && !c.Warning.empty(), "the same clamp again: warned, unchanged");
  PSI_CHECK(
    psi::SettingTable().size() == static_cast<size_t>(psi::Setting::Count), "one row per setting");
  for (size_t i = 0; i < psi::SettingTable().size(); ++i)
  {
    PSI_CHECK(psi::SettingTable()[i].Id == static_cast<psi::Setting>(i), "row %zu in order", i);
  }
}

void CheckAuto()
{
  psi::Settings s;
  PSI_CHECK(!psi::UsesComputeProjector(s) && psi::UsesSilhouettes(s), "'Auto' projection");
  s.Projector = psi::Projectors::ComputeShader;
  s.Decomposition = psi::Decompositions::Fan;
  PSI_CHECK(psi::UsesComputeProjector(s) && !psi::UsesSilhouettes(s), "asked for");
  PSI_CHECK(!psi::UsesMarchingTetrahedra(s, false) && psi::UsesMarchingTetrahedra(s, true),
    "'Auto' isosurfaces follow early discard");
  s.EarlyDiscard = false;
  PSI_CHECK(!psi::UsesMarchingTetrahedra(s, true), "'Auto' isosurfaces without early discard");
  s.IsosurfaceMethod = psi::IsosurfaceMethods::MarchingTetrahedra;
  PSI_CHECK(psi::UsesMarchingTetrahedra(s, false), "marching tetrahedra asked for");
  PSI_CHECK(!psi::UsesAdaptiveSampling(s, 0.5 * psi::AdaptiveAutoDeviation) &&
      psi::UsesAdaptiveSampling(s, 2 * psi::AdaptiveAutoDeviation),
    "'Auto' adaptive sampling follows the table's deviation");
  s.AdaptiveSampling = psi::AdaptiveModes::Off;
  PSI_CHECK(!psi::UsesAdaptiveSampling(s, 1), "adaptive sampling off");
  psi::InteractionSettings i;
  const double budget = i.InteractiveBudget;
  PSI_CHECK(!psi::UsesVolumeLOD(i, 0.5 * budget) && psi::UsesVolumeLOD(i, 2 * budget),
    "'Auto' interaction follows the budget");
  i.InteractionMode = psi::InteractionModes::FullFrame;
  PSI_CHECK(!psi::UsesVolumeLOD(i, 100), "'Full frame' never draws the level of detail");
  i.InteractionMode = psi::InteractionModes::ParaViewSurface;
  PSI_CHECK(!psi::UsesVolumeLOD(i, 100), "'ParaView surface' leaves the choice to ParaView");
  i.InteractionMode = psi::InteractionModes::VolumeLOD;
  PSI_CHECK(psi::UsesVolumeLOD(i, 0), "'Volume LOD' always");
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::printf("usage: TestSettings XML/PsiVolumeRepresentation.xml\n");
    return EXIT_FAILURE;
  }
  vtkNew<vtkPVXMLParser> parser;
  parser->SetFileName(argv[1]);
  PSI_CHECK(parser->Parse() != 0, "%s does not parse", argv[1]);
  if (vtkPVXMLElement* root = parser->GetRootElement())
  {
    CheckXML(root);
  }
  CheckClamp();
  CheckAuto();
  std::printf("%s: %d failures\n", psitest::Failures() ? "FAILED" : "passed", psitest::Failures());
  return psitest::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
