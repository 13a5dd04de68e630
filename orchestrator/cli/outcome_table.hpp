#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// The outcome table of a study (the JSON of GET /api/studies/ID/outcomes) as aligned text: one row
// per grid point, its axis values, the finished cases n, and P(stick), P(bounce), P(break-up)
// with their 95 % Wilson intervals, then the undetermined and failed counts, the mean retained
// mass fraction, the results whose deposit is in pieces and those flagged outside the
// small-strain range. `speed_unit` (if given) labels the impact-speed column.
std::string format_outcome_table(const nlohmann::ordered_json& table, const std::string& speed_unit = "");

// The unit of a study's impact speeds: m/s for a physical study (its base's "units"), d/tau
// otherwise (docs/MODEL.md 1.2).
std::string speed_unit_label(const nlohmann::ordered_json& study_document);

}  // namespace aerobreak
