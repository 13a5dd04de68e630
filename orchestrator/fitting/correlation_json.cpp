#include "orchestrator/fitting/correlation_json.hpp"

#include <cmath>

#include "orchestrator/fitting/correlation_json_parts.hpp"

namespace aerobreak {
namespace {

nlohmann::ordered_json provenance_json(const Provenance& provenance) {
  return {{"study", provenance.study},
          {"result_set_hash", provenance.result_set_hash},
          {"result_set_version", provenance.result_set_version},
          {"aerobreak_version", provenance.aerobreak_version}};
}

nlohmann::ordered_json request_json(const CorrelationRequest& request) {
  nlohmann::ordered_json covariates = nlohmann::ordered_json::array();
  for (const auto& covariate : request.covariates)
    covariates.push_back({{"axis", covariate.axis}, {"transform", covariate.logarithmic ? "log" : "linear"}});
  return {{"speed_axis",
           request.speed_axis.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(request.speed_axis)},
          {"covariates", covariates},
          {"size_axis",
           request.size_axis.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(request.size_axis)},
          {"levels", request.levels},
          {"confidence", 0.95}};
}

template <typename Fit>
void add_lines(nlohmann::ordered_json& fits, const std::vector<Fit>& list) {
  for (const auto& fit : list) fits.push_back(summary_line(fit));
}

template <typename Fit>
const Fit* find(const std::vector<Fit>& list, const std::string& name) {
  for (const auto& fit : list)
    if (fit.common.name == name) return &fit;
  return nullptr;
}

}  // namespace

nlohmann::ordered_json grid_points_json(const CorrelationSet& set) {
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const auto& point : set.grid_points) points.push_back(grid_point_json(point));
  return {{"name", kGridPointsName}, {"kind", "grid-points"}, {"status", "ok"},
          {"confidence", 0.95},      {"interval", "wilson"},  {"provenance", provenance_json(set.provenance)},
          {"grid_points", points}};
}

nlohmann::ordered_json correlation_summary_json(const CorrelationSet& set) {
  nlohmann::ordered_json fits = nlohmann::ordered_json::array();
  add_lines(fits, set.logistic);
  add_lines(fits, set.multinomial);
  add_lines(fits, set.scaling);
  add_lines(fits, set.retained_fraction);
  // One per grid point with re-entrained fragments: named here, each in full under its name.
  nlohmann::ordered_json fragment_fits = nlohmann::ordered_json::array();
  for (const auto& fit : set.fragment_sizes) fragment_fits.push_back(fit.common.name);
  return {{"format", "aerobreak-correlations"},
          {"format_version", 1},
          {"provenance", provenance_json(set.provenance)},
          {"request", request_json(set.request)},
          {"seconds", set.seconds},
          {"grid_points", {{"count", set.grid_points.size()}, {"document", kGridPointsName}}},
          {"fits", fits},
          {"fragment_sizes", fragment_fits}};
}

std::optional<nlohmann::ordered_json> fit_json(const CorrelationSet& set, const std::string& name, int curve_points) {
  if (name == kGridPointsName) return grid_points_json(set);
  nlohmann::ordered_json json;
  if (const auto* fit = find(set.logistic, name))
    json = full_json(*fit, curve_points);
  else if (const auto* fit = find(set.multinomial, name))
    json = full_json(*fit, curve_points);
  else if (const auto* fit = find(set.scaling, name))
    json = full_json(*fit, curve_points);
  else if (const auto* fit = find(set.retained_fraction, name))
    json = full_json(*fit, curve_points);
  else if (const auto* fit = find(set.fragment_sizes, name))
    json = full_json(*fit, curve_points);
  else
    return std::nullopt;
  json["provenance"] = provenance_json(set.provenance);
  json["request"] = request_json(set.request);
  return json;
}

std::vector<std::string> fit_names(const CorrelationSet& set) {
  std::vector<std::string> names{kGridPointsName};
  const auto add = [&names](const auto& list) {
    for (const auto& fit : list) names.push_back(fit.common.name);
  };
  add(set.logistic);
  add(set.multinomial);
  add(set.scaling);
  add(set.retained_fraction);
  add(set.fragment_sizes);
  return names;
}

}  // namespace aerobreak
