#include "PsiSettings.h"

#include "PsiIntegrationMethods.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <utility>

namespace psi
{

IsosurfaceList Settings::Isosurfaces() const
{
  return IsosurfaceList::Normalize(
    this->IsosurfaceValues, this->IsosurfaceOpacities, this->IsosurfaceOpacity);
}

// The value of a member, unclamped (SetClamped clamps first).
void SetValue(Settings& s, Setting id, double value);
void SetValue(InteractionSettings& s, Setting id, double value);

namespace
{
// A member's value as a number, and a number as a member's value: the XML's numbers meet the
// typed enumerations here and in the setters only.
template <typename T>
double AsNumber(T value)
{
  if constexpr (std::is_enum<T>::value)
  {
    return static_cast<double>(static_cast<int>(value));
  }
  else
  {
    return static_cast<double>(value);
  }
}

template <typename T>
void Assign(T& member, double value)
{
  if constexpr (std::is_enum<T>::value)
  {
    member = static_cast<T>(static_cast<int>(value));
  }
  else if constexpr (std::is_same<T, bool>::value)
  {
    member = value != 0;
  }
  else
  {
    member = static_cast<T>(value);
  }
}

constexpr bool IsProperty(const char* where)
{
  return where[0] == 'P'; // PROPERTY, not MAPPER
}

std::string Number(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

// The clamp of setting `id` in `s`, the struct of its kind (SetClamped).
template <typename Struct>
std::string Clamp(Struct& s, Setting id, double value)
{
  const SettingInfo& info = GetSettingInfo(id);
  if (info.Interaction != std::is_same<Struct, InteractionSettings>::value)
  {
    return std::string("'Psi Volume' ") + info.Name + " is not a setting of this kind.";
  }
  // NaN is out of every range; it becomes the lower bound
  const double used = std::isnan(value) ? info.Min : std::min(std::max(value, info.Min), info.Max);
  const bool whole = info.Kind != SettingKind::Real;
  const double kept = whole ? std::floor(used) : used;
  SetValue(s, id, kept);
  if (kept == value)
  {
    return "";
  }
  return std::string("'Psi Volume' ") + info.Name + " = " + Number(value) +
    (whole ? " is not one of its values (" : " is outside its range (") + Number(info.Min) +
    " to " + Number(info.Max) + "): " + Number(ValueOf(s, id)) + " is used.";
}

// The clamp, and whether it changed the value (Change).
template <typename Struct>
SettingChange ChangeOf(Struct& s, Setting id, double value)
{
  const double before = ValueOf(s, id);
  std::string warning = Clamp(s, id, value);
  return { ValueOf(s, id) != before, std::move(warning) };
}
} // namespace

#define PSI_SETTING_ROW_ENUM(Name, Type, Default, Last)                                            \
  { Setting::Name, #Name, SettingKind::Enumeration, AsNumber(Type::Default), 0,                    \
    AsNumber(Type::Last), true, interaction },
#define PSI_SETTING_ROW_NUMBER(Name, Type, Default, Min, Max, Where)                               \
  { Setting::Name, #Name,                                                                          \
    std::is_integral<Type>::value ? SettingKind::Integer : SettingKind::Real, Default, Min, Max,   \
    IsProperty(#Where), interaction },
#define PSI_SETTING_ROW_BOOL(Name, Default, Where)                                                 \
  { Setting::Name, #Name, SettingKind::Boolean, AsNumber(Default), 0, 1, IsProperty(#Where),       \
    interaction },

const std::vector<SettingInfo>& SettingTable()
{
  static const std::vector<SettingInfo> table = []
  {
    bool interaction = false;
    std::vector<SettingInfo> rows{ PSI_RENDER_SETTINGS(
      PSI_SETTING_ROW_ENUM, PSI_SETTING_ROW_NUMBER, PSI_SETTING_ROW_BOOL) };
    interaction = true;
    const std::vector<SettingInfo> more{ PSI_INTERACTION_SETTINGS(
      PSI_SETTING_ROW_ENUM, PSI_SETTING_ROW_NUMBER, PSI_SETTING_ROW_BOOL) };
    rows.insert(rows.end(), more.begin(), more.end());
    return rows;
  }();
  return table;
}

const SettingInfo& GetSettingInfo(Setting id)
{
  return SettingTable()[static_cast<size_t>(id)];
}

#define PSI_SETTING_GET(Name, ...)                                                                 \
  case Setting::Name:                                                                              \
    return AsNumber(s.Name);
#define PSI_SETTING_SET(Name, ...)                                                                 \
  case Setting::Name:                                                                              \
    Assign(s.Name, value);                                                                         \
    return;

double ValueOf(const Settings& s, Setting id)
{
  switch (id)
  {
    PSI_RENDER_SETTINGS(PSI_SETTING_GET, PSI_SETTING_GET, PSI_SETTING_GET)
    default:
      return std::nan("");
  }
}

double ValueOf(const InteractionSettings& s, Setting id)
{
  switch (id)
  {
    PSI_INTERACTION_SETTINGS(PSI_SETTING_GET, PSI_SETTING_GET, PSI_SETTING_GET)
    default:
      return std::nan("");
  }
}

void SetValue(Settings& s, Setting id, double value)
{
  switch (id)
  {
    PSI_RENDER_SETTINGS(PSI_SETTING_SET, PSI_SETTING_SET, PSI_SETTING_SET)
    default:
      return;
  }
}

void SetValue(InteractionSettings& s, Setting id, double value)
{
  switch (id)
  {
    PSI_INTERACTION_SETTINGS(PSI_SETTING_SET, PSI_SETTING_SET, PSI_SETTING_SET)
    default:
      return;
  }
}

std::string SetClamped(Settings& s, Setting id, double value)
{
  return Clamp(s, id, value);
}

std::string SetClamped(InteractionSettings& s, Setting id, double value)
{
  return Clamp(s, id, value);
}

SettingChange Change(Settings& s, Setting id, double value)
{
  return ChangeOf(s, id, value);
}

SettingChange Change(InteractionSettings& s, Setting id, double value)
{
  return ChangeOf(s, id, value);
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

bool UsesVolumeLOD(const InteractionSettings& s, double lastStillSeconds)
{
  return s.InteractionMode == InteractionModes::VolumeLOD ||
    (s.InteractionMode == InteractionModes::Auto && lastStillSeconds > s.InteractiveBudget);
}

} // namespace psi
