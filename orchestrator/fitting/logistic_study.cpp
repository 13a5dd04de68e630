// The logistic models of a whole study: which responses, which groups, pooled or not.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "orchestrator/fitting/logistic_models.hpp"
#include "orchestrator/fitting/parallel_tasks.hpp"

namespace aerobreak {
namespace {

std::vector<Outcome> responses_present(const CaseOutcomeTable& table) {
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
std::vector<Eigen::VectorXd> group_covariate_points(const CaseOutcomeTable& table, const std::vector<CaseGroup>& groups,
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

std::vector<LogisticFit> fit_logistic_models(const CaseOutcomeTable& table, const std::vector<CaseGroup>& groups,
                                             const CorrelationRequest& request) {
  CorrelationRequest per_group = request;
  per_group.covariates.clear();
  std::vector<std::size_t> all_points(table.grid_points.size());
  std::iota(all_points.begin(), all_points.end(), 0);
  std::vector<const CaseOutcome*> all_cases;
  for (const CaseOutcome& c : table.cases) all_cases.push_back(&c);
  const auto by_point = cases_by_point(table);
  const auto covariate_points = group_covariate_points(table, groups, request);
  const bool pooled = groups.size() > 1;
  // Each fit is a task; the tasks run on every core (run_in_parallel), results in this order.
  std::vector<std::function<LogisticFit()>> tasks;
  for (const Outcome response : responses_present(table)) {
    const std::string prefix(to_string(response));
    const auto speed_fit = [&, response, prefix](const std::string& label, const nlohmann::ordered_json& axes,
                                                 const std::vector<std::size_t>& points, bool all) {
      const CorrelationRequest* ask = all ? &request : &per_group;
      tasks.push_back([&, response, prefix, label, axes, points = &points, all, ask] {
        return fit_logistic(named(prefix + ".speed." + label, axes), response, "impact_speed",
                            speed_rows(table, by_point, *points, response, *ask), *ask,
                            all ? covariate_points : std::vector<Eigen::VectorXd>{});
      });
    };
    const auto energy_fit = [&, response, prefix](const std::string& label, const nlohmann::ordered_json& axes,
                                                  const std::vector<const CaseOutcome*>& cases, bool all) {
      const CorrelationRequest* ask = all ? &request : &per_group;
      tasks.push_back([&, response, prefix, label, axes, cases = &cases, all, ask] {
        return fit_logistic(named(prefix + ".energy." + label, axes), response, "energy_per_contact",
                            energy_rows(table, *cases, response, *ask), *ask,
                            all ? covariate_points : std::vector<Eigen::VectorXd>{});
      });
    };
    if (!request.speed_axis.empty()) {
      for (const CaseGroup& group : groups) speed_fit(group.label, group.axes, group.grid_points, false);
      if (pooled) speed_fit("pooled", nlohmann::ordered_json::object(), all_points, true);
    }
    for (const CaseGroup& group : groups) energy_fit(group.label, group.axes, group.cases, false);
    if (pooled) energy_fit("pooled", nlohmann::ordered_json::object(), all_cases, true);
  }
  return run_in_parallel(tasks);
}

namespace {

// The distinct sizes among the rows of a size-pooled model (its one covariate), for its critical doses.
std::vector<Eigen::VectorXd> row_sizes(const DoseData& rows) {
  std::vector<Eigen::VectorXd> sizes;
  for (const auto& values : rows.covariate_values)
    if (std::none_of(sizes.begin(), sizes.end(), [&](const Eigen::VectorXd& seen) { return seen == values; }))
      sizes.push_back(values);
  return sizes;
}

}  // namespace

std::vector<LogisticFit> fit_size_pooled_models(const CaseOutcomeTable& table, const CorrelationRequest& request) {
  if (request.speed_axis.empty() || request.size_axis.empty()) return {};
  CorrelationRequest over_sizes = request;
  over_sizes.covariates = {{request.size_axis, true}};
  const auto by_point = cases_by_point(table);
  const auto groups = group_cases(table, request.speed_axis, request.size_axis);
  std::vector<std::function<LogisticFit()>> tasks;
  for (const Outcome response : responses_present(table))
    for (const CaseGroup& group : groups)
      tasks.push_back([&, response, group = &group] {
        const auto rows = speed_rows(table, by_point, group->grid_points, response, over_sizes);
        return fit_logistic(named(std::string(to_string(response)) + ".speed.sizes." + group->label, group->axes), response,
                            "impact_speed", rows, over_sizes, row_sizes(rows));
      });
  return run_in_parallel(tasks);
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
