#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// The cases of one combination of the non-speed axes (e.g. one N and one gamma/k_n): the unit of the
// per-group fits. Groups are numbered in grid order (g1, g2, ...). With `pooled_axis` (e.g. N) that
// axis is left out of the combination too: the groups of the fits pooled over it.
struct CaseGroup {
  std::string label;                                             // "g1", "g2", ...
  nlohmann::ordered_json axes = nlohmann::ordered_json::object();  // the non-speed axes' values
  std::vector<std::size_t> grid_points;
  std::vector<const CaseOutcome*> cases;
};

std::vector<CaseGroup> group_cases(const CaseOutcomeTable& table, const std::string& speed_axis,
                                   const std::string& pooled_axis = {});

// The cases of each grid point, by grid-point index.
std::vector<std::vector<const CaseOutcome*>> cases_by_point(const CaseOutcomeTable& table);

// The value of `axis` at a grid point as a number; NaN when absent or not a number.
double axis_number(const nlohmann::ordered_json& grid_point, const std::string& axis);

// The determined cases of a set (undetermined ones carry no outcome to fit).
std::vector<const CaseOutcome*> determined_cases(const std::vector<const CaseOutcome*>& cases);

// How many of the cases left the small-strain range.
std::size_t small_strain_count(const std::vector<const CaseOutcome*>& cases);

}  // namespace aerobreak
