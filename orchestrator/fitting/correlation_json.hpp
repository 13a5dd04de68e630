#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// The documents of schemas/correlation.schema.json.

// Everything at a glance: provenance, the grid-point aggregates and one line per fit (name, kind,
// status, group, n and its headline numbers: critical values, exponents, tau).
nlohmann::ordered_json correlation_summary_json(const CorrelationSet& set);

// One fit in full: coefficients, covariance, goodness of fit, validity box, provenance, the data
// it was fitted to and its curve at `curve_points` points over its validity box with the 95 %
// band. nullopt when the set has no fit of that name.
std::optional<nlohmann::ordered_json> fit_json(const CorrelationSet& set, const std::string& name, int curve_points = 50);

// The names of every fit, in summary order.
std::vector<std::string> fit_names(const CorrelationSet& set);

}  // namespace aerobreak
