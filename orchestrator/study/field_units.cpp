#include "orchestrator/study/field_units.hpp"

#include <array>
#include <string_view>

#include "orchestrator/study/study_axes.hpp"

namespace aerobreak {
namespace {

// The unit of a dimensionless field: "1" in this table and in exported files, empty in what
// case_field_unit and study_axis_unit give.
constexpr std::string_view kDimensionless = "1";

// `reduced_spelling`: for a field of physical cases only (reduced empty), its unit in the reduced
// units, which the export writes for such an axis of a reduced table.
struct FieldUnit {
  std::string_view pointer;
  std::string_view reduced;
  std::string_view physical;
  std::string_view reduced_spelling = {};
};

// The fields of schemas/case.schema.json with a unit, and the numbers a study sweeps most that have
// none ("1"); every other field is a count, a ratio, a flag or a name. A field of one system only
// has an empty unit in the other.
constexpr std::array<FieldUnit, 28> kFieldUnits{{
    {"/impact/speed", "d/tau", "m/s"},
    {"/impact/angle", "deg", "deg"},
    {"/impact/gap", "d", "d"},
    {"/material/youngs_modulus", "", "Pa", "m/(d tau^2)"},
    {"/material/density", "", "kg/m^3", "m/d^3"},
    {"/material/surface_energy", "", "J/m^2", "m/tau^2"},
    {"/material/diameter", "", "m", "d"},
    {"/material/poisson_ratio", kDimensionless, kDimensionless},
    {"/material/gamma_over_kn", kDimensionless, kDimensionless},
    {"/wall/material/youngs_modulus", "", "Pa", "m/(d tau^2)"},
    {"/wall/material/surface_energy", "", "J/m^2", "m/tau^2"},
    {"/model/friction", kDimensionless, kDimensionless},
    {"/model/damping/restitution", kDimensionless, kDimensionless},
    {"/model/damping/dissipative_time", "tau", "tau"},
    {"/model/rolling/critical_displacement", "d", "d"},
    {"/model/van_der_waals/hamaker", "k_n d^2", "k_n d^2"},
    {"/model/van_der_waals/min_separation", "d", "d"},
    {"/model/van_der_waals/cutoff", "d", "d"},
    {"/run/time_limit", "tau", "tau"},
    {"/run/time_limit_s", "", "s", "s"},
    {"/run/snapshot_interval", "tau", "tau"},
    {"/run/time_step", "tau", "tau"},
    {"/run/settle/quiet_window", "tau", "tau"},
    {"/cluster/file/default_radius", "d", "d"},
    {"/cluster/generator/primaries", kDimensionless, kDimensionless},
    {"/cluster/generator/fractal_dimension", kDimensionless, kDimensionless},
    {"/cluster/generator/prefactor", kDimensionless, kDimensionless},
    {"/cluster/generator/geometric_standard_deviation", kDimensionless, kDimensionless},
}};

const FieldUnit* field_unit(const std::string& pointer) {
  for (const auto& field : kFieldUnits)
    if (field.pointer == pointer) return &field;
  return nullptr;
}

}  // namespace

std::string case_field_unit(const std::string& pointer, bool physical) {
  const FieldUnit* field = field_unit(pointer);
  if (!field) return "";
  const std::string_view unit = physical ? field->physical : field->reduced;
  return unit == kDimensionless ? "" : std::string(unit);
}

std::string exported_axis_unit(const std::string& axis_name, bool physical) {
  const FieldUnit* field = field_unit(axis_name.starts_with("/") ? axis_name : axis_pointer(axis_name));
  if (!field) return "unknown";
  if (physical) return std::string(field->physical);
  return std::string(field->reduced.empty() ? field->reduced_spelling : field->reduced);
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
