#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// The critical-speed table of a study (from the summary of GET /api/studies/ID/correlations): a
// section per group the fits carry, a row per outcome with the speeds at which P crosses 0.1, 0.5
// and 0.9, their 95 % profile-likelihood intervals, the cases fitted and how the fit went
// (Firth's estimate where the outcomes separate); the fits without a transition over the speeds
// run folded into a few lines below. `dose` is "impact_speed" or "energy_per_contact"; `system` is the
// study's units (study_units.hpp), which label the speeds (m/s or d/tau) and the groups' values.
std::string format_critical_table(const nlohmann::ordered_json& summary, const std::string& dose,
                                  const std::string& system);

// What the columns of the critical-value tables mean.
std::string critical_table_legend();

// The other fits of the summary, one line each: name, status, and the headline numbers.
std::string format_fit_list(const nlohmann::ordered_json& summary);

}  // namespace aerobreak
