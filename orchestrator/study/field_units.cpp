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

std::string case_field_unit(const std::string& pointer, bool physical) {
  for (const auto& field : kFieldUnits)
    if (field.pointer == pointer) return std::string(physical ? field.physical : field.reduced);
  return "";
}

std::string study_axis_unit(const std::string& axis_name, const std::string& system) {
  const std::string pointer = axis_pointer(axis_name);
  if (system != "mixed") return case_field_unit(pointer, system == "physical");
  const std::string physical = case_field_unit(pointer, true);
  return physical == case_field_unit(pointer, false) ? physical : "";
}

std::string point_unit_system(const nlohmann::ordered_json& axis_values, const std::string& study_system) {
  const auto units = axis_values.find("/units");
  return units != axis_values.end() && units->is_string() ? units->get<std::string>() : study_system;
}

}  // namespace aerobreak
