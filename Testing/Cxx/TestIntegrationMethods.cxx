// Every integration method against the reference of the model it approximates, over Moreland's
// sweeps (Moreland 2004 dissertation Figs. 6.5-6.11: D = 0.001, 0.1, 1, 100 over the (front, back)
// parameter plane), plus the hard cases of PsiHardCases.h: D = 0, tau = 0, tau_b = tau_f exactly
// and within 1e-12, tau D from 1e-9 to 1e6, alpha = 1 and just below, luminance outside [0, 1],
// non-finite input.
// Also the table of methods itself (psi::IntegrationMethodTable): consistent, and equal to the
// IntegrationMethod enumeration of XML/PsiVolumeRepresentation.xml (argv[1], default the source
// tree's) in (value, text), which is what the properties panel and Python see.
#include "PsiHardCases.h"
#include "PsiIntegrationMethods.h"
#include "PsiPartialPreIntegrationTable.h"
#include "PsiReferenceIntegrals.h"
#include "PsiSettings.h"
#include "PsiTestCheck.h"

#include "vtkNew.h"
#include "vtkPVXMLElement.h"
#include "vtkPVXMLParser.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using psi::Method;

bool Finite(const psi::Rgba& c)
{
  return std::all_of(c.begin(), c.end(), [](double v) { return std::isfinite(v); });
}

double MaxDiff(const psi::Rgba& a, const psi::Rgba& b)
{
  double m = 0;
  for (int k = 0; k < 4; ++k)
  {
    m = std::max(m, std::abs(a[k] - b[k]));
  }
  return m;
}

// The sweep of Moreland's error plots: opacity values (front, back) over a grid, luminance 1 at
// the back and 0 at the front (the worst case for luminance averaging), length D.
struct SweepError
{
  double Max = 0, Mean = 0;
};

SweepError Sweep(Method m, double D, const psi::PartialPreIntegrationTable& table, int n = 24)
{
  SweepError e;
  int count = 0;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      psi::TFSegment s;
      s.af = (i + 0.5) / n;
      s.ab = (j + 0.5) / n;
      s.Lf = { { 0, 0, 0 } };
      s.Lb = { { 1, 1, 1 } };
      s.D = D;
      s.unit = 1;
      const double err = MaxDiff(psi::Integrate(m, s, &table), psi::IntegrateReferenceFor(m, s));
      e.Max = std::max(e.Max, err);
      e.Mean += err;
      ++count;
    }
  }
  e.Mean /= count;
  return e;
}

// Every <IntVectorProperty name="IntegrationMethod"> under `e`.
void FindIntegrationMethodProperties(vtkPVXMLElement* e, std::vector<vtkPVXMLElement*>& found)
{
  if (std::string(e->GetName() ? e->GetName() : "") == "IntVectorProperty" &&
    std::string(e->GetAttributeOrEmpty("name")) == "IntegrationMethod")
  {
    found.push_back(e);
  }
  for (unsigned int i = 0; i < e->GetNumberOfNestedElements(); ++i)
  {
    FindIntegrationMethodProperties(e->GetNestedElement(i), found);
  }
}

// The differences between the IntegrationMethod enumeration(s) of the proxy XML `xml` and the
// table, one message each (none: they agree). Entries are compared as (value, text) pairs both
// ways, so a missing, extra, renumbered or misnamed row or entry is reported.
std::vector<std::string> CompareXmlWithTable(const std::string& xml, int* defaultValue = nullptr)
{
  std::vector<std::string> problems;
  vtkNew<vtkPVXMLParser> parser;
  parser->SuppressErrorMessagesOn();
  if (!parser->Parse(xml.c_str()) || !parser->GetRootElement())
  {
    return { "the XML does not parse" };
  }
  std::vector<vtkPVXMLElement*> props;
  FindIntegrationMethodProperties(parser->GetRootElement(), props);
  if (props.empty())
  {
    return { "no IntVectorProperty named IntegrationMethod" };
  }
  const auto& table = psi::IntegrationMethodTable();
  std::set<std::pair<int, std::string>> rows;
  for (const psi::IntegrationMethodInfo& info : table)
  {
    rows.insert({ static_cast<int>(info.Id), info.Name });
  }
  for (vtkPVXMLElement* prop : props)
  {
    if (defaultValue)
    {
      prop->GetScalarAttribute("default_values", defaultValue);
    }
    vtkPVXMLElement* domain = prop->FindNestedElementByName("EnumerationDomain");
    if (!domain)
    {
      problems.push_back("IntegrationMethod has no EnumerationDomain");
      continue;
    }
    std::set<std::pair<int, std::string>> entries;
    for (unsigned int i = 0; i < domain->GetNumberOfNestedElements(); ++i)
    {
      vtkPVXMLElement* entry = domain->GetNestedElement(i);
      if (std::string(entry->GetName() ? entry->GetName() : "") != "Entry")
      {
        continue;
      }
      int value = -1;
      const char* text = entry->GetAttribute("text");
      if (!entry->GetScalarAttribute("value", &value) || !text)
      {
        problems.push_back("an Entry without value or text");
        continue;
      }
      if (!entries.insert({ value, text }).second)
      {
        problems.push_back("duplicate Entry " + std::to_string(value) + " '" + text + "'");
      }
    }
    for (const auto& e : entries)
    {
      if (!rows.count(e))
      {
        problems.push_back("XML Entry " + std::to_string(e.first) + " '" + e.second +
          "' is not a row of psi::IntegrationMethodTable()");
      }
    }
    for (const auto& r : rows)
    {
      if (!entries.count(r))
      {
        problems.push_back("table row " + std::to_string(r.first) + " '" + r.second +
          "' has no XML Entry with that value and text");
      }
    }
  }
  return problems;
}

std::string ReadFile(const char* path)
{
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return in ? ss.str() : std::string();
}

// Replaces the first occurrence of `from` (which must be there) in `s`.
std::string Edited(std::string s, const std::string& from, const std::string& to)
{
  const auto pos = s.find(from);
  return pos == std::string::npos ? std::string() : s.replace(pos, from.size(), to);
}

// The settings take the table's values, clamped (the mapper clamps through psi::SetClamped,
// TestMapperSettings); returns the default method.
int CheckSettingsTakeTheTable()
{
  psi::Settings s;
  const int last = psi::NumberOfIntegrationMethods() - 1;
  psi::SetClamped(s, psi::Setting::IntegrationMethod, -3);
  PSI_CHECK(static_cast<int>(s.IntegrationMethod) == 0, "clamped below");
  psi::SetClamped(s, psi::Setting::IntegrationMethod, last + 5);
  PSI_CHECK(static_cast<int>(s.IntegrationMethod) == last, "clamped above");
  return static_cast<int>(psi::Settings().IntegrationMethod);
}

void CheckTable(const char* xmlPath)
{
  const auto& table = psi::IntegrationMethodTable();
  PSI_CHECK(static_cast<int>(table.size()) == psi::NumberOfIntegrationMethods() &&
      psi::NumberOfIntegrationMethods() == static_cast<int>(Method::Count),
    "table size %d, Method::Count %d", static_cast<int>(table.size()),
    static_cast<int>(Method::Count));
  std::set<std::string> names, glslNames;
  for (size_t i = 0; i < table.size(); ++i)
  {
    const psi::IntegrationMethodInfo& info = table[i];
    PSI_CHECK(static_cast<size_t>(info.Id) == i, "row %d has Id %d", static_cast<int>(i),
      static_cast<int>(info.Id));
    PSI_CHECK(info.Name && *info.Name && names.insert(info.Name).second, "row %d: name",
      static_cast<int>(i));
    PSI_CHECK(info.GlslName && std::string(info.GlslName).rfind("PsiIntegrate", 0) == 0 &&
        glslNames.insert(info.GlslName).second,
      "%s: GLSL name must be a unique Shaders/PsiIntegrate*.glsl", info.Name);
    PSI_CHECK(info.Integrate != nullptr, "%s: no CPU integrator", info.Name);
    PSI_CHECK(!(info.NeedsPsiTable && info.NeedsPreIntegrationTable), "%s: two tables", info.Name);
    PSI_CHECK(psi::FindIntegrationMethod(std::string(info.Name)) == &info &&
        psi::FindIntegrationMethod(static_cast<int>(i)) == &info &&
        &psi::GetIntegrationMethodInfo(info.Id) == &info &&
        std::string(psi::MethodName(info.Id)) == info.Name &&
        psi::UsesLinearOpacity(info.Id) == (info.Model == psi::OpticalModel::LinearOpacity),
      "%s: lookups disagree with the row", info.Name);
  }
  PSI_CHECK(psi::FindIntegrationMethod(std::string("No Such Method")) == nullptr &&
      psi::FindIntegrationMethod(-1) == nullptr &&
      psi::FindIntegrationMethod(psi::NumberOfIntegrationMethods()) == nullptr &&
      std::string(psi::MethodName(Method::Count)) == "Unknown",
    "lookups outside the table");

  const int last = psi::NumberOfIntegrationMethods() - 1;
  const int settingsDefault = CheckSettingsTakeTheTable();

  // The panel's enumeration against the table.
  const std::string xml = ReadFile(xmlPath);
  PSI_CHECK(!xml.empty(), "cannot read %s", xmlPath);
  int xmlDefault = -1;
  const std::vector<std::string> problems = CompareXmlWithTable(xml, &xmlDefault);
  for (const std::string& p : problems)
  {
    std::printf("  %s\n", p.c_str());
  }
  PSI_CHECK(
    problems.empty(), "%s: IntegrationMethod enumeration differs from the table (above)", xmlPath);
  PSI_CHECK(xmlDefault == settingsDefault, "XML default_values %d, settings default %d", xmlDefault,
    settingsDefault);
  // ... and the comparison does see a missing, extra or misnamed entry.
  const std::string first = std::string("text=\"") + table[0].Name + "\"";
  const std::string lastEntry =
    "<Entry value=\"" + std::to_string(last) + "\" text=\"" + table[last].Name + "\" />";
  for (const std::string& bad :
    { Edited(xml, lastEntry, ""), Edited(xml, first, "text=\"Avg\""),
      Edited(xml, lastEntry,
        lastEntry + "<Entry value=\"" + std::to_string(last + 1) + "\" text=\"New Method\" />") })
  {
    PSI_CHECK(!bad.empty() && !CompareXmlWithTable(bad).empty(),
      "an edited enumeration must differ from the table");
  }
  if (problems.empty())
  {
    std::printf("IntegrationMethod enumeration of %s matches the %d rows of the table\n", xmlPath,
      psi::NumberOfIntegrationMethods());
  }
}

// Special functions against SciPy's dawsn / erfcx (values printed by scipy.special, 17 digits).
void CheckSpecialFunctions()
{
  const double dawson[][2] = { { 0.05, 0.049916749940509222 }, { 0.19, 0.18549268702269875 },
    { 0.2, 0.19475103336802793 }, { 0.5, 0.42443638350202229 }, { 1.0, 0.5380795069127684 },
    { 2.0, 0.301340388923792 }, { 3.7, 0.14075117411541541 }, { 10.0, 0.050253847187598538 },
    { 45.0, 0.011113856630059881 } };
  for (const auto& v : dawson)
  {
    const double rel = std::abs(psi::Dawson(v[0]) - v[1]) / v[1];
    PSI_CHECK(rel < 1e-13, "Dawson(%g) relative error %g", v[0], rel);
    PSI_CHECK(psi::Dawson(-v[0]) == -psi::Dawson(v[0]), "Dawson is odd");
  }
  const double erfcx[][2] = { { 0.0, 1 }, { 0.3, 0.73459933456765536 }, { 1.0, 0.427583576155807 },
    { 5.0, 0.11070463773306861 }, { 19.9, 0.028315573983185766 }, { 20.1, 0.028034523526966875 },
    { 30.0, 0.018795888861416754 }, { 1000.0, 0.00056418930145338763 } };
  for (const auto& v : erfcx)
  {
    const double rel = std::abs(psi::Erfcx(v[0]) - v[1]) / v[1];
    PSI_CHECK(rel < 1e-12, "erfcx(%g) relative error %g", v[0], rel);
  }
}

// Closed-form Psi (Williams-Max-Stein, stable branches) against quadrature over 15 decades of
// tau D and every ratio, including tau_b = tau_f exactly and within 1e-12.
void CheckClosedFormPsi()
{
  double worstClosed = 0;
  for (double a = 1e-9; a <= 1e6; a *= 4.3)
  {
    for (double b = 1e-9; b <= 1e6; b *= 4.3)
    {
      for (double rel : { 0.0, 1e-12, -1e-12, 1.0 })
      {
        const double ab = rel == 1.0 ? a : b * (1 + rel);
        const double q = psi::Psi(ab, b), c = psi::PsiClosedForm(ab, b);
        worstClosed = std::max(worstClosed, std::abs(q - c));
      }
    }
  }
  // The erfc fit behind erfcx has 1.2e-7 relative error; Rybicki's Dawson ~2e-7.
  PSI_CHECK(worstClosed < 1e-10, "closed-form Psi vs quadrature: %g", worstClosed);
  std::printf(
    "closed-form Psi (WMS) within %.2g of quadrature for tau D in [1e-9, 1e6]\n", worstClosed);
}

// The linear-opacity reference against brute force: 10^6 homogeneous slabs, each composited
// exactly (slab opacity from the local alpha), front to back; with alpha = 1 at both ends the
// first slab is opaque and gives the front luminance, which the reference must return too.
void CheckLinearOpacityReference()
{
  for (const auto& c : { std::array<double, 3>{ { 0.2, 0.7, 1.0 } },
         std::array<double, 3>{ { 0.9, 0.1, 3.0 } }, std::array<double, 3>{ { 1.0, 0.3, 1.0 } },
         std::array<double, 3>{ { 0.3, 1.0, 0.5 } }, std::array<double, 3>{ { 1.0, 1.0, 1.0 } } })
  {
    psi::TFSegment s;
    s.af = c[0];
    s.ab = c[1];
    s.D = c[2];
    s.Lf = { { 0.1, 0.1, 0.1 } };
    s.Lb = { { 0.9, 0.9, 0.9 } };
    const int N = 1000000;
    double color = 0, trans = 1;
    for (int i = 0; i < N; ++i)
    {
      const double u = (i + 0.5) / N;
      const double a = s.af + (s.ab - s.af) * u;
      const double slab = 1 - std::pow(1 - a, s.D / N); // opacity of D/N units at alpha per unit
      color += trans * slab * (s.Lf[0] + (s.Lb[0] - s.Lf[0]) * u);
      trans *= 1 - slab;
    }
    const psi::Rgba r = psi::IntegrateReferenceLinearOpacity(s);
    PSI_CHECK(std::abs(r[0] - color) < 2e-5 && std::abs(r[3] - (1 - trans)) < 2e-5,
      "linear-opacity reference (%g, %g, D=%g): %g/%g vs brute force %g/%g", c[0], c[1], c[2], r[0],
      r[3], color, 1 - trans);
  }
}

// Moreland's sweeps: error of each method against its own model's reference, within the bound
// of its table row; returns those bounds.
std::vector<double> CheckSweeps(const psi::PartialPreIntegrationTable& table)
{
  std::printf("\n%-34s %10s %10s %10s %10s   (max error over the alpha plane)\n", "method",
    "D=0.001", "D=0.1", "D=1", "D=100");
  // each method's bound is its table row's SweepErrorBound
  std::vector<double> bounds;
  for (const psi::IntegrationMethodInfo& row : psi::IntegrationMethodTable())
  {
    bounds.push_back(row.SweepErrorBound);
  }
  double sweepMax[static_cast<int>(Method::Count)][4];
  for (int mi = 0; mi < static_cast<int>(Method::Count); ++mi)
  {
    const Method m = static_cast<Method>(mi);
    std::printf("%-34s", psi::MethodName(m));
    double worst = 0;
    int di = 0;
    for (double D : { 0.001, 0.1, 1.0, 100.0 })
    {
      const SweepError e = Sweep(m, D, table);
      std::printf(" %10.2e", e.Max);
      worst = std::max(worst, e.Max);
      sweepMax[mi][di++] = e.Max;
    }
    std::printf("\n");
    PSI_CHECK(worst < bounds[mi], "%s: sweep error %g above its bound %g", psi::MethodName(m),
      worst, bounds[mi]);
  }
  // Ordering the papers report (Moreland 2004 dissertation Table 6.4 and Figs. 6.9-6.11): the
  // improved linear opacity approximation beats averaging opacity; partial pre-integration beats
  // averaging.
  const auto atD1 = [&](Method m) { return sweepMax[static_cast<int>(m)][2]; };
  PSI_CHECK(atD1(Method::LinearOpacityImproved) < atD1(Method::LinearLuminanceAverageOpacity),
    "improved linear-opacity approximation should beat the initial one at D = 1");
  PSI_CHECK(atD1(Method::PartialPreIntegration) < 0.01 * atD1(Method::Average),
    "partial pre-integration should be two orders better than averaging at D = 1");
  return bounds;
}

// Hard cases: every method gives finite output within its bound of the reference: the case's own
// bound where it has one for the method, else the sweep bound.
void CheckHardCases(const psi::PartialPreIntegrationTable& table, const std::vector<double>& bounds)
{
  const auto hard = psitest::HardCases(false);
  for (const psitest::HardCase& h : hard)
  {
    for (int mi = 0; mi < static_cast<int>(Method::Count); ++mi)
    {
      const Method m = static_cast<Method>(mi);
      const psi::Rgba c = psi::Integrate(m, h.S, &table);
      const psi::Rgba r = psi::IntegrateReferenceFor(m, h.S);
      PSI_CHECK(Finite(c) && Finite(r), "%s, %s: non-finite result", h.Name, psi::MethodName(m));
      // Same bound as the sweeps, scaled by the luminance range for the out-of-range case.
      const double scale = std::max(1.0, std::abs(h.S.Lb[0] - h.S.Lf[0]));
      const double own = h.Bound ? h.Bound(m, h.S) : -1.0;
      const double bound = own >= 0 ? own + 1e-12 : bounds[mi] * scale + 1e-9;
      PSI_CHECK(MaxDiff(c, r) <= bound, "%s, %s: error %g above %g", h.Name, psi::MethodName(m),
        MaxDiff(c, r), bound);
    }
  }
  // NaN input must stay contained: it is never turned into a plausible-looking color.
  {
    psi::TFSegment s = hard[0].S;
    s.af = NAN;
    const psi::Rgba c = psi::Integrate(Method::LinearExact, s, &table);
    PSI_CHECK(!Finite(c), "NaN attenuation must propagate to the caller (the mapper drops it)");
  }
}
} // namespace

int main(int argc, char* argv[])
{
  CheckTable(argc > 1 ? argv[1] : PSI_REPRESENTATION_XML);
  const psi::PartialPreIntegrationTable& table = psi::GetDefaultPsiTable();
  CheckSpecialFunctions();
  CheckClosedFormPsi();
  CheckLinearOpacityReference();
  const std::vector<double> bounds = CheckSweeps(table);
  CheckHardCases(table, bounds);
  return psitest::Report("TestIntegrationMethods");
}
