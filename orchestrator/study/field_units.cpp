#include "orchestrator/study/field_units.hpp"

#include <array>
#include <string_view>

#include "orchestrator/study/study_axes.hpp"

namespace aerobreak {
namespace {

struct FieldUnit {
  std::string_view pointer;
  std::string_view reduced;
  std::string_view physical;
};

// The dimensioned fields of schemas/case.schema.json; every other field is a count, a ratio, a flag
// or a name. A field of one system only has an empty unit in the other.
constexpr std::array<FieldUnit, 20> kFieldUnits{{
    {"/impact/speed", "d/tau", "m/s"},
    {"/impact/angle", "deg", "deg"},
    {"/impact/gap", "d", "d"},
    {"/material/youngs_modulus", "", "Pa"},
    {"/material/density", "", "kg/m^3"},
    {"/material/surface_energy", "", "J/m^2"},
    {"/material/diameter", "", "m"},
    {"/wall/material/youngs_modulus", "", "Pa"},
    {"/wall/material/surface_energy", "", "J/m^2"},
    {"/model/damping/dissipative_time", "tau", "tau"},
    {"/model/rolling/critical_displacement", "d", "d"},
    {"/model/van_der_waals/hamaker", "k_n d^2", "k_n d^2"},
    {"/model/van_der_waals/min_separation", "d", "d"},
    {"/model/van_der_waals/cutoff", "d", "d"},
    {"/run/time_limit", "tau", "tau"},
    {"/run/time_limit_s", "", "s"},
    {"/run/snapshot_interval", "tau", "tau"},
    {"/run/time_step", "tau", "tau"},
    {"/run/settle/quiet_window", "tau", "tau"},
    {"/cluster/file/default_radius", "d", "d"},
}};

}  // namespace

bool physical_study(const nlohmann::ordered_json& study_document) {
  const auto base = study_document.find("base");
  return base != study_document.end() && base->is_object() && base->value("units", std::string()) == "physical";
}

std::string case_field_unit(const std::string& pointer, bool physical) {
  for (const auto& field : kFieldUnits)
    if (field.pointer == pointer) return std::string(physical ? field.physical : field.reduced);
  return "";
}

std::string study_axis_unit(const std::string& axis_name, bool physical) {
  return case_field_unit(axis_pointer(axis_name), physical);
}

}  // namespace aerobreak
