#pragma once
#include <nlohmann/json.hpp>
#include <vector>

#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/fitting/estimate_json.hpp"

// The JSON of each part of a correlation set (correlation_json.hpp puts them together).
namespace aerobreak {

nlohmann::ordered_json grid_point_json(const GridPointSummary& point);

// The fields every fit carries (FitCommon).
nlohmann::ordered_json common_json(const FitCommon& common);

// The summary fields every fit shares: name, kind, status, detail, group, cases.
nlohmann::ordered_json summary_common(const FitCommon& common);

// One line of the summary: name, kind, status, group, n and the headline numbers.
nlohmann::ordered_json summary_line(const LogisticFit& fit);
nlohmann::ordered_json summary_line(const MultinomialFit& fit);
nlohmann::ordered_json summary_line(const ScalingFit& fit);
nlohmann::ordered_json summary_line(const RetainedFractionFit& fit);

// The whole fit, with its data and its curve at `points` points.
nlohmann::ordered_json full_json(const LogisticFit& fit, int points);
nlohmann::ordered_json full_json(const MultinomialFit& fit, int points);
nlohmann::ordered_json full_json(const ScalingFit& fit, int points);
nlohmann::ordered_json full_json(const RetainedFractionFit& fit, int points);
nlohmann::ordered_json full_json(const FragmentSizeFit& fit, int points);

// `count` values spread evenly in log from exactly `low` to exactly `high`.
std::vector<double> log_spaced(double low, double high, int count);

}  // namespace aerobreak
