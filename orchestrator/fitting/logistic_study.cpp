// The logistic models of a whole study: which responses, which groups, pooled along which axes.
#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "orchestrator/fitting/logistic_models.hpp"
#include "orchestrator/fitting/parallel_tasks.hpp"

namespace aerobreak {
namespace {

std::vector<ImpactOutcome> responses_present(const CaseOutcomeTable& table) {
  std::vector<ImpactOutcome> present;
  for (const ImpactOutcome outcome : kDeterminedOutcomes)
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

// The distinct covariate values among the rows of a pooled model, for its critical doses.
std::vector<Eigen::VectorXd> distinct_covariates(const DoseData& rows) {
  std::vector<Eigen::VectorXd> points;
  for (const auto& values : rows.covariate_values)
    if (std::none_of(points.begin(), points.end(), [&](const Eigen::VectorXd& seen) { return seen == values; }))
      points.push_back(values);
  return points;
}

// The request's covariates that take more than one value among a condition's grid points: the
// axes its pooled models pool along (a covariate constant in the condition adds nothing to pool).
CorrelationRequest condition_request(const CaseOutcomeTable& table, const CaseGroup& condition,
                                     const CorrelationRequest& request) {
  CorrelationRequest pooled = request;
  pooled.covariates.clear();
  for (const auto& covariate : request.covariates) {
    std::set<double> values;
    for (const std::size_t g : condition.grid_points) values.insert(axis_number(table.grid_points[g], covariate.axis));
    if (values.size() > 1) pooled.covariates.push_back(covariate);
  }
  return pooled;
}

// The fits of one response: per group (no covariate) and, per condition whose groups differ in a
// covariate, pooled along the covariates (OUTCOME.DOSE.pooled.cK), in log speed and in log energy.
struct ResponseFits {
  const CaseOutcomeTable& table;
  const std::vector<std::vector<const CaseOutcome*>>& by_point;
  const std::vector<CaseGroup>& groups;
  const std::vector<CaseGroup>& conditions;
  const std::vector<CorrelationRequest>& condition_requests;
  const CorrelationRequest& per_group;
  std::vector<std::function<LogisticFit()>>& tasks;

  void speed_fit(ImpactOutcome response, const std::string& label, const CaseGroup& group,
                 const CorrelationRequest* ask) {
    tasks.push_back([this, response, label, group = &group, ask] {
      const auto rows = speed_rows(table, by_point, group->grid_points, response, *ask);
      return fit_logistic(named(std::string(to_string(response)) + ".speed." + label, group->axes), response,
                          "impact_speed", rows, *ask,
                          ask->covariates.empty() ? std::vector<Eigen::VectorXd>{} : distinct_covariates(rows));
    });
  }

  void energy_fit(ImpactOutcome response, const std::string& label, const CaseGroup& group,
                  const CorrelationRequest* ask) {
    tasks.push_back([this, response, label, group = &group, ask] {
      const auto rows = energy_rows(table, group->cases, response, *ask);
      return fit_logistic(named(std::string(to_string(response)) + ".energy." + label, group->axes), response,
                          "energy_per_contact", rows, *ask,
                          ask->covariates.empty() ? std::vector<Eigen::VectorXd>{} : distinct_covariates(rows));
    });
  }

  void add(ImpactOutcome response) {
    if (!per_group.speed_axis.empty()) {
      for (const CaseGroup& group : groups) speed_fit(response, group.label, group, &per_group);
      for (std::size_t c = 0; c < conditions.size(); ++c)
        if (!condition_requests[c].covariates.empty())  // one group: nothing to pool along
          speed_fit(response, "pooled." + conditions[c].label, conditions[c], &condition_requests[c]);
    }
    for (const CaseGroup& group : groups) energy_fit(response, group.label, group, &per_group);
    for (std::size_t c = 0; c < conditions.size(); ++c)
      if (!condition_requests[c].covariates.empty())
        energy_fit(response, "pooled." + conditions[c].label, conditions[c], &condition_requests[c]);
  }
};

}  // namespace

std::vector<LogisticFit> fit_logistic_models(const CaseOutcomeTable& table, const std::vector<CaseGroup>& groups,
                                             const CorrelationRequest& request) {
  CorrelationRequest per_group = request;
  per_group.covariates.clear();
  const auto by_point = cases_by_point(table);
  const auto conditions = condition_groups(table, request);
  std::vector<CorrelationRequest> condition_requests;
  for (const CaseGroup& condition : conditions)
    condition_requests.push_back(condition_request(table, condition, request));
  // Each fit is a task; the tasks run on every core (run_in_parallel), results in this order.
  std::vector<std::function<LogisticFit()>> tasks;
  ResponseFits fits{table, by_point, groups, conditions, condition_requests, per_group, tasks};
  for (const ImpactOutcome response : responses_present(table)) fits.add(response);
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
