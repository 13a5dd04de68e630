#include <cmath>
#include <set>

#include "orchestrator/fitting/critical_dose.hpp"
#include "orchestrator/fitting/goodness_of_fit.hpp"
#include "orchestrator/fitting/secondary_fits.hpp"

namespace aerobreak {
namespace {

// Whether a per-group fit belongs to a condition: every axis of the condition has its value there.
bool in_condition(const LogisticFit& fit, const CaseGroup& condition) {
  for (const auto& [axis, value] : condition.axes.items())
    if (!fit.common.group.contains(axis) || fit.common.group.at(axis) != value) return false;
  return true;
}

// The groups' v_p with a bounded interval, from the per-group speed fits of one response in one
// condition (the groups whose axes other than the modelled ones are the condition's).
std::vector<ScalingPoint> scaling_points(const std::vector<LogisticFit>& logistic, ImpactOutcome response, double level,
                                         const CaseGroup& condition) {
  std::vector<ScalingPoint> points;
  for (const LogisticFit& fit : logistic) {
    if (fit.response != response || fit.dose != "impact_speed" || !fit.covariates.empty() ||
        !in_condition(fit, condition))
      continue;
    for (const CriticalValue& value : fit.critical)
      if (value.level == level && value.estimate && value.lower && value.upper && *value.upper > *value.lower)
        points.push_back({fit.common.group, *value.estimate, *value.lower, *value.upper});
  }
  return points;
}

// The modelled axes (the request's covariates) that are numbers > 0 at every point and take more
// than one value.
std::vector<std::string> varying_axes(const std::vector<ScalingPoint>& points, const CorrelationRequest& request) {
  std::vector<std::string> axes;
  if (points.empty()) return axes;
  for (const auto& covariate : request.covariates) {
    const std::string& axis = covariate.axis;
    std::set<double> values;
    bool usable = true;
    for (const ScalingPoint& point : points) {
      const double value = axis_number(point.group, axis);
      usable = usable && value > 0.0;
      values.insert(value);
    }
    if (usable && values.size() > 1) axes.push_back(axis);
  }
  return axes;
}

void solve_weighted(ScalingFit& fit) {
  const auto m = static_cast<Eigen::Index>(fit.points.size());
  const auto p = static_cast<Eigen::Index>(fit.axes.size() + 1);
  Eigen::MatrixXd x(m, p);
  Eigen::VectorXd y(m), w(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const ScalingPoint& point = fit.points[static_cast<std::size_t>(i)];
    x(i, 0) = 1.0;
    for (Eigen::Index k = 1; k < p; ++k)
      x(i, k) = std::log(axis_number(point.group, fit.axes[static_cast<std::size_t>(k - 1)]));
    y[i] = std::log(point.critical_speed);
    const double sigma = (std::log(point.upper) - std::log(point.lower)) / (2.0 * kZ95);
    w[i] = 1.0 / (sigma * sigma);
  }
  const Eigen::MatrixXd information = x.transpose() * w.asDiagonal() * x;
  const Eigen::MatrixXd covariance = information.ldlt().solve(Eigen::MatrixXd::Identity(p, p));
  fit.common.coefficients = covariance * x.transpose() * w.asDiagonal() * y;
  const Eigen::VectorXd residual = y - x * fit.common.coefficients;
  const double chi2 = residual.dot(w.asDiagonal() * residual);
  const double df = static_cast<double>(m - p);
  fit.scale_factor = df > 0.0 ? std::sqrt(std::max(1.0, chi2 / df)) : 1.0;
  fit.common.covariance = covariance * fit.scale_factor * fit.scale_factor;
  fit.common.goodness_of_fit = {{"chi-square", chi2, df, chi_square_upper_tail(chi2, df)}};
}

ScalingFit fit_one(const std::vector<LogisticFit>& logistic, ImpactOutcome response, double level,
                   const CaseGroup& condition, const CorrelationRequest& request) {
  ScalingFit fit;
  fit.response = response;
  fit.level = level;
  const int percent = static_cast<int>(std::lround(level * 100.0));
  fit.common.name =
      "scaling." + std::string(to_string(response)) + ".v" + std::to_string(percent) + "." + condition.label;
  fit.common.kind = "scaling";
  fit.common.group = condition.axes;
  fit.points = scaling_points(logistic, response, level, condition);
  fit.axes = varying_axes(fit.points, request);
  fit.common.groups = fit.points.size();
  fit.common.parameters = {"log(prefactor)"};
  for (const auto& axis : fit.axes) fit.common.parameters.push_back("exponent of " + axis);
  for (const auto& axis : fit.axes) {
    InputRange range{axis, INFINITY, -INFINITY};
    for (const ScalingPoint& point : fit.points) {
      range.min = std::min(range.min, axis_number(point.group, axis));
      range.max = std::max(range.max, axis_number(point.group, axis));
    }
    fit.common.validity.push_back(range);
  }
  if (fit.axes.empty() || fit.points.size() < fit.axes.size() + 1) {
    fit.common.status = FitStatus::insufficient_data;
    fit.common.detail = "too few points: " + std::to_string(fit.points.size()) + " group(s) with a bounded v" +
                        std::to_string(percent) + " interval over " + std::to_string(fit.axes.size()) +
                        " varying modelled axis/axes in this condition";
    return fit;
  }
  solve_weighted(fit);
  if (fit.points.size() == fit.axes.size() + 1)
    fit.common.detail = "as many groups as parameters: the power law passes through every v" + std::to_string(percent) +
                        " and nothing tests it; its intervals come from the groups' intervals alone";
  return fit;
}

}  // namespace

std::vector<ScalingFit> fit_scaling_laws(const std::vector<LogisticFit>& logistic,
                                         const std::vector<CaseGroup>& conditions, const CorrelationRequest& request) {
  std::vector<ScalingFit> fits;
  if (request.speed_axis.empty() || request.covariates.empty()) return fits;
  std::set<ImpactOutcome> responses;
  for (const LogisticFit& fit : logistic) responses.insert(fit.response);
  for (const ImpactOutcome response : responses)
    for (const CaseGroup& condition : conditions) {
      ScalingFit fit = fit_one(logistic, response, 0.5, condition, request);
      for (const LogisticFit& source : logistic)
        if (source.response == response && source.dose == "impact_speed" && source.covariates.empty() &&
            in_condition(source, condition)) {
          fit.common.cases += source.common.cases;
          fit.common.small_strain_cases += source.common.small_strain_cases;
        }
      fits.push_back(std::move(fit));
    }
  return fits;
}

}  // namespace aerobreak
