// The logistic models of a whole study: which responses, which groups, pooled or not.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "orchestrator/fitting/logistic_models.hpp"

namespace aerobreak {
namespace {

std::vector<Outcome> responses_present(const OutcomeTable& table) {
  std::vector<Outcome> present;
  for (const Outcome outcome : kDeterminedOutcomes)
    for (const CaseOutcome& c : table.cases)
      if (c.outcome == outcome) {
        present.push_back(outcome);
        break;
      }
  return present;
}

FitCommon named(const std::string& name, const nlohmann::ordered_json& group) {
  FitCommon common;
  common.name = name;
  common.kind = "logistic";
  common.group = group;
  return common;
}

// The distinct covariate values of the groups, for the pooled models' critical doses.
std::vector<Eigen::VectorXd> group_covariate_points(const OutcomeTable& table, const std::vector<CaseGroup>& groups,
                                                    const CorrelationRequest& request) {
  std::vector<Eigen::VectorXd> points;
  if (request.covariates.empty()) return points;
  for (const CaseGroup& group : groups) {
    Eigen::VectorXd point(static_cast<Eigen::Index>(request.covariates.size()));
    for (std::size_t k = 0; k < request.covariates.size(); ++k)
      point[static_cast<Eigen::Index>(k)] = axis_number(table.grid_points[group.grid_points.front()], request.covariates[k].axis);
    const bool seen = std::any_of(points.begin(), points.end(), [&](const Eigen::VectorXd& p) { return p == point; });
    if (point.allFinite() && !seen) points.push_back(point);
  }
  return points;
}

}  // namespace

std::vector<LogisticFit> fit_logistic_models(const OutcomeTable& table, const std::vector<CaseGroup>& groups,
                                             const CorrelationRequest& request) {
  CorrelationRequest per_group = request;
  per_group.covariates.clear();
  std::vector<std::size_t> all_points(table.grid_points.size());
  std::iota(all_points.begin(), all_points.end(), 0);
  std::vector<const CaseOutcome*> all_cases;
  for (const CaseOutcome& c : table.cases) all_cases.push_back(&c);
  const auto covariate_points = group_covariate_points(table, groups, request);
  const bool pooled = groups.size() > 1;
  std::vector<LogisticFit> fits;
  for (const Outcome response : responses_present(table)) {
    const std::string prefix(to_string(response));
    if (!request.speed_axis.empty()) {
      for (const CaseGroup& group : groups)
        fits.push_back(fit_logistic(named(prefix + ".speed." + group.label, group.axes), response, "impact_speed",
                                    speed_rows(table, group.grid_points, response, per_group), per_group, {}));
      if (pooled)
        fits.push_back(fit_logistic(named(prefix + ".speed.pooled", {}), response, "impact_speed",
                                    speed_rows(table, all_points, response, request), request, covariate_points));
    }
    for (const CaseGroup& group : groups)
      fits.push_back(fit_logistic(named(prefix + ".energy." + group.label, group.axes), response, "energy_per_contact",
                                  energy_rows(table, group.cases, response, per_group), per_group, {}));
    if (pooled)
      fits.push_back(fit_logistic(named(prefix + ".energy.pooled", {}), response, "energy_per_contact",
                                  energy_rows(table, all_cases, response, request), request, covariate_points));
  }
  return fits;
}

BandPoint LogisticFit::probability(double dose_value, const Eigen::VectorXd& covariate_values) const {
  const Eigen::VectorXd& beta = common.coefficients;
  Eigen::VectorXd x(beta.size());
  x[0] = 1.0;
  x[1] = std::log(dose_value);
  for (Eigen::Index k = 0; k + 2 < x.size(); ++k) {
    const Covariate& covariate = covariates[static_cast<std::size_t>(k)];
    x[2 + k] = covariate.logarithmic ? std::log(covariate_values[k]) : covariate_values[k];
  }
  const double eta = x.dot(beta);
  const double half_width = kZ95 * std::sqrt(std::max(0.0, x.dot(common.covariance * x)));
  return {logistic(eta), logistic(eta - half_width), logistic(eta + half_width)};
}

}  // namespace aerobreak
