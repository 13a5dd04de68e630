#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// The documents of schemas/correlation.schema.json.

// The name of the document of the per-grid-point aggregates, served beside the fits.
inline constexpr const char* kGridPointsName = "grid-points";

// Everything at a glance: provenance, the number of grid points and one line per fit (name, kind,
// status, group, n, validity box and its headline numbers: a logistic fit's coefficients and a
// group's critical values, exponents), and the names of the fragment-size fits.
nlohmann::ordered_json correlation_summary_json(const CorrelationSet& set);

// The per-grid-point aggregates (outcome probabilities with Wilson intervals, means with their
// standard errors, re-entrained fragments): the document named "grid-points".
nlohmann::ordered_json grid_points_json(const CorrelationSet& set);

// One fit in full: coefficients, covariance, goodness of fit, validity box, provenance, the data
// it was fitted to and its curve at `curve_points` points over its validity box with the 95 %
// band. nullopt when the set has no fit of that name.
std::optional<nlohmann::ordered_json> fit_json(const CorrelationSet& set, const std::string& name,
                                               int curve_points = 50);

// The names of every document: "grid-points", then every fit in summary order.
std::vector<std::string> fit_names(const CorrelationSet& set);

// A logistic fit back from its full document (fit_json): what predicting from it and tabulating it
// need (name, status, group, response, dose, covariates, coefficients, covariance, validity box,
// critical values, the trials and successes of its rows; not its design). Every number as stored:
// JSON keeps doubles exactly. std::runtime_error on a document that is not such a fit.
LogisticFit logistic_fit_from_json(const nlohmann::ordered_json& document);

}  // namespace aerobreak
