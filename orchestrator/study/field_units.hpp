#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// Units of the values a study or case writes (schemas/case.schema.json): SI for a physical case
// ("units": "physical"), the reduced units d, m and tau = sqrt(m/k_n) otherwise (docs/MODEL.md 1.2).

// The unit the case field at `pointer` is written in: "m/s" or "d/tau" for /impact/speed, "deg" for
// /impact/angle, "Pa" for /material/youngs_modulus, "tau" for /model/damping/dissipative_time (in
// both systems), ...; empty for a count, a ratio, a flag or a name (N, gamma/k_n, mu, a method).
std::string case_field_unit(const std::string& pointer, bool physical);

// The unit of a study axis (a name or a pointer) as the exported tables write it (docs/EXPORT.md):
// "1" for a dimensionless number, the reduced spelling of an SI unit ("m/(d tau^2)" for a Young's
// modulus) in a reduced table, "unknown" for a field the table above does not list.
std::string exported_axis_unit(const std::string& axis_name, bool physical);

// The same for a study axis, by its name in the study (an alias such as "impact_speed", or a pointer),
// in a unit system of study_units.hpp: "physical", "reduced", or "mixed" (an axis sets /units), where
// only a unit both systems share is given.
std::string study_axis_unit(const std::string& axis_name, const std::string& system);

// The unit system of one grid point or fit group of a study in `study_system`: its "/units" where an
// axis sets it, the study's otherwise.
std::string point_unit_system(const nlohmann::ordered_json& axis_values, const std::string& study_system);

// Whether the case field at `pointer` is plotted in log scale (it spans decades: speeds, moduli,
// N, gamma/k_n); false for a field the table does not list. A covariate of the correlations on such
// a field enters the pooled models as its logarithm.
bool field_log_scale(const std::string& pointer);

// A study axis as the API and the web page show it (schemas/openapi.json, AxisDescription).
struct AxisDescription {
  std::string name;     // as the study names it: an alias or a JSON pointer
  std::string pointer;  // the case field it sets
  std::string alias;    // its short name (named_case_fields); empty: none
  std::string label;    // "impact speed v₀"; a field without one: the name
  std::string symbol;   // "v₀", for legends; a field without one: the alias or the name
  std::string unit;     // study_axis_unit in `system`; empty: none (a count, a ratio, a name, mixed units)
  bool log_scale;       // plotted in log scale (decades); false for a field without a label
};

// The description of axis `axis_name` in unit system `system` ("physical", "reduced" or "mixed").
AxisDescription describe_axis(const std::string& axis_name, const std::string& system);

}  // namespace aerobreak
