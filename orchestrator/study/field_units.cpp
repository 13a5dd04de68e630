#include "orchestrator/study/field_units.hpp"

#include <array>
#include <string_view>

#include "orchestrator/study/study_axes.hpp"

namespace aerobreak {
namespace {

// The unit of a dimensionless field: "1" in this table and in exported files, empty in what
// case_field_unit and study_axis_unit give.
constexpr std::string_view kDimensionless = "1";

// One case field as studies, tables and the web page name it: its unit in each system and, for the
// page and the API (GET /api/studies/ID: axes), a label, the symbol a plot's legend writes and
// whether its axis is plotted in log scale. `reduced_spelling`: for a field of physical cases only
// (reduced empty), its unit in the reduced units, which the export writes for such an axis of a
// reduced table.
struct CaseField {
  std::string_view pointer;
  std::string_view label;
  std::string_view symbol;
  bool log_scale;
  std::string_view reduced;
  std::string_view physical;
  std::string_view reduced_spelling = {};
};

constexpr bool kLog = true;
constexpr bool kLinear = false;

// The fields of schemas/case.schema.json with a unit, and the numbers, flags and names a study sweeps
// most that have none ("1"; the export writes "1" for any flag or name); every other field is
// labelled by its pointer. A field of one system only
// has an empty unit in the other. Log scale for the fields that span decades (speeds, stiffnesses,
// sizes, adhesion, time steps); linear for angles, ratios in [0, 1] and dimensions near 2.
constexpr std::array<CaseField, 30> kCaseFields{{
    {"/impact/speed", "impact speed v₀", "v₀", kLog, "d/tau", "m/s"},
    {"/impact/angle", "impact angle", "θ", kLinear, "deg", "deg"},
    {"/impact/gap", "initial gap to the wall", "gap", kLinear, "d", "d"},
    {"/material/youngs_modulus", "Young's modulus E", "E", kLog, "", "Pa", "m/(d tau^2)"},
    {"/material/density", "density ρ", "ρ", kLog, "", "kg/m^3", "m/d^3"},
    {"/material/surface_energy", "surface energy γ", "γ", kLog, "", "J/m^2", "m/tau^2"},
    {"/material/diameter", "primary diameter d", "d", kLog, "", "m", "d"},
    {"/material/poisson_ratio", "Poisson's ratio ν", "ν", kLinear, kDimensionless, kDimensionless},
    {"/material/gamma_over_kn", "γ/k_n", "γ/k_n", kLog, kDimensionless, kDimensionless},
    {"/wall/adhesive", "adhesive wall", "adhesive", kLinear, kDimensionless, kDimensionless},
    {"/wall/material/youngs_modulus", "wall's Young's modulus", "E_wall", kLog, "", "Pa", "m/(d tau^2)"},
    {"/wall/material/surface_energy", "wall's surface energy", "γ_wall", kLog, "", "J/m^2", "m/tau^2"},
    {"/model/friction", "friction coefficient μ", "μ", kLinear, kDimensionless, kDimensionless},
    {"/model/damping/restitution", "target restitution e", "e", kLinear, kDimensionless, kDimensionless},
    {"/model/damping/dissipative_time", "visco-elastic dissipative constant A", "A", kLog, "tau", "tau"},
    {"/model/rolling/critical_displacement", "critical rolling displacement ξ_crit", "ξ_crit", kLog, "d", "d"},
    {"/model/van_der_waals/hamaker", "Hamaker constant A_H", "A_H", kLog, "k_n d^2", "k_n d^2"},
    {"/model/van_der_waals/min_separation", "van der Waals minimum separation z₀", "z₀", kLog, "d", "d"},
    {"/model/van_der_waals/cutoff", "van der Waals cutoff", "cutoff", kLinear, "d", "d"},
    {"/run/time_limit", "time limit", "t_max", kLinear, "tau", "tau"},
    {"/run/time_limit_s", "time limit", "t_max", kLinear, "", "s", "s"},
    {"/run/snapshot_interval", "snapshot interval", "Δt_snap", kLinear, "tau", "tau"},
    {"/run/time_step", "time step Δt", "Δt", kLog, "tau", "tau"},
    {"/run/settle/quiet_window", "settling quiet window", "t_quiet", kLinear, "tau", "tau"},
    {"/cluster/file/default_radius", "default primary radius", "r", kLinear, "d", "d"},
    {"/cluster/generator/method", "cluster generator", "generator", kLinear, kDimensionless, kDimensionless},
    {"/cluster/generator/primaries", "primaries N", "N", kLog, kDimensionless, kDimensionless},
    {"/cluster/generator/fractal_dimension", "fractal dimension D_f", "D_f", kLinear, kDimensionless, kDimensionless},
    {"/cluster/generator/prefactor", "fractal prefactor k_f", "k_f", kLinear, kDimensionless, kDimensionless},
    {"/cluster/generator/geometric_standard_deviation", "geometric standard deviation σ_g", "σ_g", kLinear,
     kDimensionless, kDimensionless},
}};

const CaseField* case_field(const std::string& pointer) {
  for (const auto& field : kCaseFields)
    if (field.pointer == pointer) return &field;
  return nullptr;
}

}  // namespace

std::string case_field_unit(const std::string& pointer, bool physical) {
  const CaseField* field = case_field(pointer);
  if (!field) return "";
  const std::string_view unit = physical ? field->physical : field->reduced;
  return unit == kDimensionless ? "" : std::string(unit);
}

std::string exported_axis_unit(const std::string& axis_name, bool physical) {
  const CaseField* field = case_field(axis_name.starts_with("/") ? axis_name : axis_pointer(axis_name));
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

bool field_log_scale(const std::string& pointer) {
  const CaseField* field = case_field(pointer);
  return field && field->log_scale;
}

AxisDescription describe_axis(const std::string& axis_name, const std::string& system) {
  AxisDescription axis{axis_name, axis_pointer(axis_name), "", axis_name, "", study_axis_unit(axis_name, system),
                       false};
  for (const auto& named : named_case_fields())
    if (named.axis_alias && named.pointer == axis.pointer) axis.alias = named.name;
  axis.symbol = axis.alias.empty() ? axis_name : axis.alias;
  if (const CaseField* field = case_field(axis.pointer)) {
    axis.label = field->label;
    axis.symbol = field->symbol;
    axis.log_scale = field->log_scale;
  }
  return axis;
}

std::string point_unit_system(const nlohmann::ordered_json& axis_values, const std::string& study_system) {
  const auto units = axis_values.find("/units");
  return units != axis_values.end() && units->is_string() ? units->get<std::string>() : study_system;
}

}  // namespace aerobreak
