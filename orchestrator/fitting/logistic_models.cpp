#include "orchestrator/fitting/logistic_models.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "orchestrator/fitting/critical_dose.hpp"
#include "orchestrator/fitting/goodness_of_fit.hpp"
#include "orchestrator/fitting/separation.hpp"

namespace aerobreak {
namespace {

double covariate_term(const Covariate& covariate, double value) {
  return covariate.logarithmic ? std::log(value) : value;
}

// Covariate values of a grid point; empty when one is missing or unusable (log of a value <= 0).
std::optional<Eigen::VectorXd> covariates_at(const nlohmann::ordered_json& grid_point,
                                             const CorrelationRequest& request) {
  Eigen::VectorXd values(static_cast<Eigen::Index>(request.covariates.size()));
  for (std::size_t k = 0; k < request.covariates.size(); ++k) {
    values[static_cast<Eigen::Index>(k)] = axis_number(grid_point, request.covariates[k].axis);
    if (!std::isfinite(values[static_cast<Eigen::Index>(k)]) ||
        (request.covariates[k].logarithmic && values[static_cast<Eigen::Index>(k)] <= 0.0))
      return std::nullopt;
  }
  return values;
}

// Appends a row; the design is built once all rows are in (build_design).
void add_row(DoseData& rows, double dose, const Eigen::VectorXd& covariates, double trials, double successes) {
  rows.dose.push_back(dose);
  rows.covariate_values.push_back(covariates);
  rows.trials.push_back(trials);
  rows.successes.push_back(successes);
}

// Columns 1, log dose, covariate terms.
void build_design(DoseData& rows, const CorrelationRequest& request) {
  const auto n = static_cast<Eigen::Index>(rows.dose.size());
  const auto k = static_cast<Eigen::Index>(request.covariates.size());
  auto& b = rows.binomial;
  b.design.resize(n, 2 + k);
  for (Eigen::Index i = 0; i < n; ++i) {
    b.design(i, 0) = 1.0;
    b.design(i, 1) = std::log(rows.dose[static_cast<std::size_t>(i)]);
    const auto& covariates = rows.covariate_values[static_cast<std::size_t>(i)];
    for (Eigen::Index j = 0; j < k; ++j)
      b.design(i, 2 + j) = covariate_term(request.covariates[static_cast<std::size_t>(j)], covariates[j]);
  }
  b.trials = Eigen::Map<const Eigen::VectorXd>(rows.trials.data(), n);
  b.successes = Eigen::Map<const Eigen::VectorXd>(rows.successes.data(), n);
}

std::set<double> distinct(const std::vector<double>& values) { return {values.begin(), values.end()}; }

}  // namespace

DoseData speed_rows(const CaseOutcomeTable& table, const std::vector<std::size_t>& grid_points, ImpactOutcome response,
                    const CorrelationRequest& request) {
  return speed_rows(table, cases_by_point(table), grid_points, response, request);
}

DoseData speed_rows(const CaseOutcomeTable& table, const std::vector<std::vector<const CaseOutcome*>>& by_point,
                    const std::vector<std::size_t>& grid_points, ImpactOutcome response,
                    const CorrelationRequest& request) {
  DoseData rows;
  for (const std::size_t g : grid_points) {
    const auto determined = determined_cases(by_point[g]);
    const double speed = axis_number(table.grid_points[g], request.speed_axis);
    const auto covariates = covariates_at(table.grid_points[g], request);
    if (determined.empty() || !(speed > 0.0) || !covariates) continue;
    const auto events = std::count_if(determined.begin(), determined.end(),
                                      [response](const CaseOutcome* c) { return c->outcome == response; });
    add_row(rows, speed, *covariates, static_cast<double>(determined.size()), static_cast<double>(events));
    rows.cases += determined.size();
    rows.small_strain += small_strain_count(determined);
    ++rows.groups;
  }
  build_design(rows, request);
  return rows;
}

DoseData energy_rows(const CaseOutcomeTable& table, const std::vector<const CaseOutcome*>& cases,
                     ImpactOutcome response, const CorrelationRequest& request) {
  DoseData rows;
  std::set<std::size_t> points;
  for (const CaseOutcome* c : determined_cases(cases)) {
    const auto covariates = covariates_at(table.grid_points[c->grid_point], request);
    if (!c->energy_per_contact || !(*c->energy_per_contact > 0.0) || !covariates) continue;
    add_row(rows, *c->energy_per_contact, *covariates, 1.0, c->outcome == response ? 1.0 : 0.0);
    ++rows.cases;
    rows.small_strain += c->small_strain_exceeded ? 1 : 0;
    points.insert(c->grid_point);
  }
  rows.groups = points.size();
  build_design(rows, request);
  return rows;
}

namespace {

// Min and max of the dose and of every covariate over the rows.
std::vector<InputRange> validity_box(const DoseData& rows, const std::string& dose, const CorrelationRequest& request) {
  std::vector<InputRange> box;
  if (rows.dose.empty()) return box;
  const auto [low, high] = std::minmax_element(rows.dose.begin(), rows.dose.end());
  box.push_back({dose, *low, *high});
  for (std::size_t k = 0; k < request.covariates.size(); ++k) {
    InputRange range{request.covariates[k].axis, INFINITY, -INFINITY};
    for (const auto& values : rows.covariate_values) {
      range.min = std::min(range.min, values[static_cast<Eigen::Index>(k)]);
      range.max = std::max(range.max, values[static_cast<Eigen::Index>(k)]);
    }
    box.push_back(range);
  }
  return box;
}

// The doses between which the outcome switches, for a one-dose model under separation: the last
// dose with none of the response and the first with nothing else (doses with both lie between).
std::optional<std::array<double, 2>> separation_bracket(const DoseData& rows) {
  if (rows.binomial.design.cols() != 2) return std::nullopt;
  double none_low = INFINITY, none_high = -INFINITY, all_low = INFINITY, all_high = -INFINITY;
  for (std::size_t i = 0; i < rows.dose.size(); ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    if (rows.binomial.successes[r] == 0.0) {
      none_low = std::min(none_low, rows.dose[i]);
      none_high = std::max(none_high, rows.dose[i]);
    } else if (rows.binomial.successes[r] == rows.binomial.trials[r]) {
      all_low = std::min(all_low, rows.dose[i]);
      all_high = std::max(all_high, rows.dose[i]);
    }
  }
  if (!std::isfinite(none_low) || !std::isfinite(all_low)) return std::nullopt;
  if (none_high < all_low) return std::array<double, 2>{none_high, all_low};  // rising with the dose
  if (all_high < none_low) return std::array<double, 2>{all_high, none_low};  // falling
  return std::nullopt;
}

// Why a data set cannot be fitted at all; empty when it can.
std::pair<FitStatus, std::string> unfittable(const DoseData& rows, ImpactOutcome response, const std::string& dose) {
  const auto& b = rows.binomial;
  const std::size_t doses = distinct(rows.dose).size();
  const auto p = static_cast<std::size_t>(b.design.cols());
  if (doses < 2 || b.design.rows() < static_cast<Eigen::Index>(p) ||
      Eigen::FullPivLU<Eigen::MatrixXd>(b.design.transpose() * b.design).rank() < b.design.cols())
    return {FitStatus::insufficient_data, "too few points: " + std::to_string(doses) + " distinct value(s) of " + dose +
                                              " among " + std::to_string(rows.cases) + " determined case(s); a slope " +
                                              "with " + std::to_string(p - 2) + " covariate(s) needs more"};
  const double events = b.successes.sum(), trials = b.trials.sum();
  if (events == 0.0 || events == trials)
    return {FitStatus::no_transition, std::string(events == 0.0 ? "no " : "only ") + std::string(to_string(response)) +
                                          " among the " + std::to_string(rows.cases) + " cases: the transition lies " +
                                          "outside the data (see the validity box)"};
  return {FitStatus::ok, {}};
}

void add_critical_values(LogisticFit& fit, const GlmFit& glm, const CorrelationRequest& request,
                         const std::vector<Eigen::VectorXd>& covariate_points) {
  const auto [low, high] = std::minmax_element(fit.data.design.col(1).begin(), fit.data.design.col(1).end());
  const double width = std::max(*high - *low, std::log(2.0));
  std::vector<Eigen::VectorXd> points = covariate_points;
  if (points.empty()) points.emplace_back();
  for (const auto& point : points) {
    CriticalDoseRequest ask;
    ask.reference = Eigen::VectorXd::Zero(fit.data.design.cols());
    ask.reference[0] = 1.0;
    nlohmann::ordered_json at = nlohmann::ordered_json::object();
    for (Eigen::Index k = 0; k < point.size(); ++k) {
      const Covariate& covariate = request.covariates[static_cast<std::size_t>(k)];
      ask.reference[2 + k] = covariate_term(covariate, point[k]);
      at[covariate.axis] = point[k];
    }
    ask.search_low = *low - 3.0 * width;
    ask.search_high = *high + 3.0 * width;
    ask.penalty = fit.method == "maximum likelihood" ? Penalty::none : Penalty::firth;
    for (const double level : request.levels) {
      ask.level = level;
      const CriticalDose dose =
          covariate_points.empty() ? critical_dose(fit.data, glm, ask) : critical_dose_delta(glm, ask);
      const auto to_dose = [](std::optional<double> x) { return x ? std::optional(std::exp(*x)) : std::nullopt; };
      fit.critical.push_back({level, at, to_dose(dose.estimate), to_dose(dose.lower), to_dose(dose.upper)});
    }
  }
}

std::vector<std::string> parameter_names(const std::string& dose, const CorrelationRequest& request) {
  std::vector<std::string> names{"intercept", "log(" + dose + ")"};
  for (const auto& covariate : request.covariates)
    names.push_back(covariate.logarithmic ? "log(" + covariate.axis + ")" : covariate.axis);
  return names;
}

// The measured crossings of a group's fit to grouped rows (one row per dose), at the request's levels.
std::vector<CriticalValue> observed_crossings(const DoseData& rows, const CorrelationRequest& request) {
  std::vector<CriticalValue> crossings;
  if (!request.covariates.empty() || distinct(rows.dose).size() != rows.dose.size()) return crossings;
  std::vector<std::pair<double, double>> points;
  for (std::size_t i = 0; i < rows.dose.size(); ++i)
    points.emplace_back(rows.dose[i], rows.successes[i] / rows.trials[i]);
  std::sort(points.begin(), points.end());
  for (const double level : request.levels)
    crossings.push_back(
        {level, nlohmann::ordered_json::object(), observed_crossing(points, level), std::nullopt, std::nullopt});
  return crossings;
}

}  // namespace

LogisticFit fit_logistic(FitCommon common, ImpactOutcome response, const std::string& dose, const DoseData& rows,
                         const CorrelationRequest& request, const std::vector<Eigen::VectorXd>& covariate_points) {
  LogisticFit fit;
  fit.common = std::move(common);
  fit.response = response;
  fit.dose = dose;
  fit.covariates = request.covariates;
  fit.method = "maximum likelihood";
  fit.data = rows.binomial;
  fit.common.cases = rows.cases;
  fit.common.groups = rows.groups;
  fit.common.small_strain_cases = rows.small_strain;
  fit.common.validity = validity_box(rows, dose, request);
  fit.common.parameters = parameter_names(dose, request);
  if (dose == "impact_speed") fit.observed = observed_crossings(rows, request);
  std::tie(fit.common.status, fit.common.detail) = unfittable(rows, response, dose);
  if (fit.common.status != FitStatus::ok) return fit;
  GlmFit glm = fit_binomial(rows.binomial);
  if (!glm.converged) {
    const auto separation = find_separation(rows.binomial, glm);
    if (!separation) {
      fit.common.status = FitStatus::not_converged;
      fit.common.detail = "maximum likelihood did not converge in " + std::to_string(glm.iterations) + " iterations";
      return fit;
    }
    fit.common.status = FitStatus::separation;
    fit.separation_complete = separation->complete;
    fit.perfectly_predicted = separation->perfectly_predicted.size();
    fit.separation_bracket = separation_bracket(rows);
    fit.common.detail = std::string(separation->complete ? "complete" : "quasi-complete") +
                        " separation: no maximum-likelihood estimate exists; Firth's penalised estimate instead";
    fit.method = "Firth penalised likelihood";
    GlmOptions firth;
    firth.penalty = Penalty::firth;
    firth.max_iterations = 200;
    glm = fit_binomial(rows.binomial, firth);
  }
  fit.common.coefficients = glm.coefficients;
  fit.common.covariance = glm.covariance;
  fit.common.log_likelihood = glm.log_likelihood;
  fit.common.deviance = glm.deviance;
  fit.common.goodness_of_fit = binomial_goodness_of_fit(rows.binomial, glm, rows.binomial.design.cols());
  add_critical_values(fit, glm, request, covariate_points);
  return fit;
}

}  // namespace aerobreak
