#include "PsiSettings.h"

#include "PsiIntegrationMethods.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace psi
{

IsosurfaceList Settings::Isosurfaces() const
{
  return IsosurfaceList::Normalize(
    this->IsosurfaceValues, this->IsosurfaceOpacities, this->IsosurfaceOpacity);
}

namespace
{
SettingInfo Int(
  Setting id, const char* name, int Settings::*member, int lo, int hi, bool property = true)
{
  return { id, name, member, nullptr, double(lo), double(hi), property };
}

SettingInfo Real(Setting id, const char* name, double Settings::*member, double lo, double hi,
  bool property = true)
{
  return { id, name, nullptr, member, lo, hi, property };
}

std::string Number(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}
} // namespace

const std::vector<SettingInfo>& SettingTable()
{
  using S = Setting;
  static const std::vector<SettingInfo> table{
    Int(S::IntegrationMethod, "IntegrationMethod", &Settings::IntegrationMethod, 0,
      NumberOfIntegrationMethods() - 1),
    Int(S::SortMethod, "SortMethod", &Settings::SortMethod, Sorts::Centroid, Sorts::MPVONC),
    Int(S::Projector, "Projector", &Settings::Projector, Projectors::GeometryShader,
      Projectors::Auto),
    Int(S::Decomposition, "Decomposition", &Settings::Decomposition, Decompositions::Silhouette,
      Decompositions::Auto),
    Int(S::TransferFunctionSamples, "TransferFunctionSamples", &Settings::TransferFunctionSamples,
      2, 1 << 16, false),
    Int(S::AdaptiveSampling, "AdaptiveSampling", &Settings::AdaptiveSampling, AdaptiveModes::Off,
      AdaptiveModes::Auto),
    Int(S::IsosurfaceMethod, "IsosurfaceMethod", &Settings::IsosurfaceMethod,
      IsosurfaceMethods::MarchingTetrahedra, IsosurfaceMethods::Auto),
    Int(S::IsosurfaceShading, "IsosurfaceShading", &Settings::IsosurfaceShading,
      IsosurfaceShadings::Smooth, IsosurfaceShadings::Unlit),
    Int(S::InteractionMode, "InteractionMode", &Settings::InteractionMode,
      InteractionModes::Auto, InteractionModes::FullFrame),
    Real(S::IsosurfaceOpacity, "IsosurfaceOpacity", &Settings::IsosurfaceOpacity, 0, 1),
    Real(S::InteractiveBudget, "InteractiveBudget", &Settings::InteractiveBudget, 0, 60),
  };
  return table;
}

const SettingInfo& GetSettingInfo(Setting id)
{
  return SettingTable()[static_cast<size_t>(id)];
}

double ValueOf(const Settings& s, Setting id)
{
  const SettingInfo& info = GetSettingInfo(id);
  return info.Int ? s.*info.Int : s.*info.Double;
}

std::string SetClamped(Settings& s, Setting id, double value)
{
  const SettingInfo& info = GetSettingInfo(id);
  // NaN is out of every range; it becomes the lower bound
  const double used = std::isnan(value) ? info.Min : std::min(std::max(value, info.Min), info.Max);
  if (info.Int)
  {
    s.*info.Int = static_cast<int>(used);
  }
  else
  {
    s.*info.Double = used;
  }
  if (used == value && (!info.Int || used == std::floor(used)))
  {
    return "";
  }
  return std::string("'Psi Volume' ") + info.Name + " = " + Number(value) +
    (info.Int ? " is not one of its values (" : " is outside its range (") + Number(info.Min) +
    " to " + Number(info.Max) + "): " + Number(ValueOf(s, id)) + " is used.";
}

const std::vector<BoolSettingInfo>& BoolSettingTable()
{
  static const std::vector<BoolSettingInfo> table{
    { "ExactPerspectiveSegments", &Settings::ExactPerspectiveSegments, false },
    { "EarlyDiscard", &Settings::EarlyDiscard },
    { "IsosurfaceUseColorMap", &Settings::IsosurfaceUseColorMap },
  };
  return table;
}

bool UsesComputeProjector(const Settings& s)
{
  return s.Projector == Projectors::ComputeShader;
}

bool UsesSilhouettes(const Settings& s)
{
  return s.Decomposition != Decompositions::Fan;
}

bool UsesMarchingTetrahedra(const Settings& s, bool zeroOpacity)
{
  return s.IsosurfaceMethod == IsosurfaceMethods::MarchingTetrahedra ||
    (s.IsosurfaceMethod == IsosurfaceMethods::Auto && s.EarlyDiscard && zeroOpacity);
}

bool UsesAdaptiveSampling(const Settings& s, double tableDeviation)
{
  return s.AdaptiveSampling == AdaptiveModes::On ||
    (s.AdaptiveSampling == AdaptiveModes::Auto && tableDeviation > AdaptiveAutoDeviation);
}

bool UsesVolumeLOD(const Settings& s, double lastStillSeconds)
{
  return s.InteractionMode == InteractionModes::VolumeLOD ||
    (s.InteractionMode == InteractionModes::Auto && lastStillSeconds > s.InteractiveBudget);
}

} // namespace psi
