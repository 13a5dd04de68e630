#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>

#include "orchestrator/fitting/mean_estimate.hpp"

// The one JSON shape of each per-grid-point estimate, wherever it is served or stored: the
// correlation documents (schemas/correlation.schema.json, $defs mean and proportion), the outcome
// table and the dashboard's grid (schemas/openapi.json, MeanEstimate and the outcomes' items).
namespace aerobreak {

// A number, or null when absent or not finite.
nlohmann::ordered_json number_or_null(const std::optional<double>& value);

// {"n", "mean", "standard_deviation", "standard_error", "ci95": [lower, upper]} (mean_estimate.hpp);
// n = 0 and the rest null without a value, everything but n and mean null with one value.
nlohmann::ordered_json mean_json(const std::optional<MeanEstimate>& estimate);

// {"count", "probability", "ci95": [lower, upper]}: `count` of the trials, with its Wilson interval
// (null without trials).
nlohmann::ordered_json proportion_json(std::size_t count, const std::optional<ProportionEstimate>& estimate);

}  // namespace aerobreak
