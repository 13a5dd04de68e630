#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// The cases of one combination of the non-speed axes (e.g. one N, one gamma/k_n and one wall): the
// unit of the per-group fits. Groups are numbered in grid order (g1, g2, ...). With `pooled_axes`
// (e.g. N) those axes are left out of the combination too: the conditions of the fits pooled along
// them (c1, c2, ...), every other axis of the study still splitting them.
struct CaseGroup {
  std::string label;                                               // "g1", "g2", ... or "c1", "c2", ...
  nlohmann::ordered_json axes = nlohmann::ordered_json::object();  // the non-speed axes' values
  std::vector<std::size_t> grid_points;
  std::vector<const CaseOutcome*> cases;
};

std::vector<CaseGroup> group_cases(const CaseOutcomeTable& table, const std::string& speed_axis,
                                   const std::vector<std::string>& pooled_axes = {}, const std::string& prefix = "g");

// The conditions of the pooled models: the combinations of every non-speed axis but the request's
// covariates (the axes the pooled models model), labelled c1, c2, ... in grid order. A fit pools
// only along the axes it models: a study's walls, gamma/k_n values (unless a covariate), generators
// or angles are never mixed into one curve.
std::vector<CaseGroup> condition_groups(const CaseOutcomeTable& table, const CorrelationRequest& request);

// The cases of each grid point, by grid-point index.
std::vector<std::vector<const CaseOutcome*>> cases_by_point(const CaseOutcomeTable& table);

// The value of `axis` at a grid point as a number; NaN when absent or not a number.
double axis_number(const nlohmann::ordered_json& grid_point, const std::string& axis);

// The determined cases of a set (undetermined ones carry no outcome to fit).
std::vector<const CaseOutcome*> determined_cases(const std::vector<const CaseOutcome*>& cases);

// How many of the cases left the small-strain range.
std::size_t small_strain_count(const std::vector<const CaseOutcome*>& cases);

}  // namespace aerobreak
