#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// Units of the values a study or case writes (schemas/case.schema.json): SI for a physical case
// ("units": "physical"), the reduced units d, m and tau = sqrt(m/k_n) otherwise (docs/MODEL.md 1.2).

// Whether a study document's base is in physical units.
bool physical_study(const nlohmann::ordered_json& study_document);

// The unit the case field at `pointer` is written in: "m/s" or "d/tau" for /impact/speed, "deg" for
// /impact/angle, "Pa" for /material/youngs_modulus, "tau" for /model/damping/dissipative_time (in
// both systems), ...; empty for a count, a ratio, a flag or a name (N, gamma/k_n, mu, a method).
std::string case_field_unit(const std::string& pointer, bool physical);

// The same for a study axis, by its name in the study (an alias such as "impact_speed", or a pointer).
std::string study_axis_unit(const std::string& axis_name, bool physical);

}  // namespace aerobreak
