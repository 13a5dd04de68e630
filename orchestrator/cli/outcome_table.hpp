#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// The outcome table of a study (the JSON of GET /api/studies/ID/outcomes) as text within 100
// columns, then its legend: a section per value of the axes other than the impact speed (or the
// first axis, without one), a row per speed with the results n, P(stick), P(bounce) and P(break-up)
// in % with their 95 % Wilson intervals, the mean retained mass fraction, the results fractured on
// the wall and those flagged outside the small-strain range, the undetermined and the failed
// cases. `system`, the study's units (study_units.hpp: "physical", "reduced" or "mixed"), gives
// each axis value its unit: SI, or d, m and tau.
std::string format_outcome_table(const nlohmann::ordered_json& table, const std::string& system);

// "/wall/adhesive = true, primaries = 32, /impact/angle = 30 deg": axis values with their units
// (`system`: the study's units, or the values' own "/units"), all but the axis `left_out`.
std::string group_title(const nlohmann::ordered_json& values, const std::string& system,
                        const std::string& left_out = "");

// The unit of the impact speeds of a study in unit system `system` (study_units.hpp): m/s for a
// physical study, d/tau for a reduced one (docs/MODEL.md 1.2), both where an axis sets /units.
std::string speed_unit_label(const std::string& system);

}  // namespace aerobreak
