#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// The critical-speed table of a study (from the summary of GET /api/studies/ID/correlations): one
// row per group and outcome, the speeds at which P crosses 0.1, 0.5 and 0.9 with their 95 %
// profile-likelihood intervals, and how the fit went (separation: Firth's estimate). `dose` is
// "impact_speed" or "energy_per_contact".
std::string format_critical_table(const nlohmann::ordered_json& summary, const std::string& dose = "impact_speed");

// The other fits of the summary, one line each: name, status, and the headline numbers.
std::string format_fit_list(const nlohmann::ordered_json& summary);

}  // namespace aerobreak
