#include <algorithm>
#include <cmath>
#include <set>

#include "orchestrator/fitting/goodness_of_fit.hpp"
#include "orchestrator/fitting/secondary_fits.hpp"

namespace aerobreak {
namespace {

RetainedFractionFit fit_one(const CaseOutcomeTable& table, const CaseGroup& group, const CorrelationRequest& request) {
  RetainedFractionFit fit;
  fit.common.name = "retained.speed." + group.label;
  fit.common.kind = "retained-fraction";
  fit.common.group = group.axes;
  fit.common.parameters = {"intercept", "log(impact_speed)"};
  std::vector<double> speeds, fractions;
  for (const CaseOutcome* c : determined_cases(group.cases)) {
    const double speed = axis_number(table.grid_points[c->grid_point], request.speed_axis);
    if (!c->retained_mass_fraction || !(speed > 0.0)) continue;
    speeds.push_back(speed);
    fractions.push_back(std::clamp(*c->retained_mass_fraction, 0.0, 1.0));
    fit.common.small_strain_cases += c->small_strain_exceeded ? 1 : 0;
  }
  fit.common.cases = speeds.size();
  const auto n = static_cast<Eigen::Index>(speeds.size());
  fit.data.design.resize(n, 2);
  fit.data.design.col(0).setOnes();
  for (Eigen::Index i = 0; i < n; ++i) fit.data.design(i, 1) = std::log(speeds[static_cast<std::size_t>(i)]);
  fit.data.trials = Eigen::VectorXd::Ones(n);
  fit.data.successes = Eigen::Map<const Eigen::VectorXd>(fractions.data(), n);
  std::set<double> distinct(speeds.begin(), speeds.end());
  fit.common.groups = distinct.size();
  if (!speeds.empty()) fit.common.validity = {{"impact_speed", *distinct.begin(), *distinct.rbegin()}};
  if (distinct.size() < 2) {
    fit.common.status = FitStatus::insufficient_data;
    fit.common.detail =
        "too few points: " + std::to_string(distinct.size()) + " distinct speed(s) with a retained fraction";
    return fit;
  }
  const GlmFit glm = fit_binomial(fit.data);
  if (!glm.converged) {
    fit.common.status = FitStatus::no_transition;
    fit.common.detail =
        "the retained fraction does not change with speed in a way a logit can follow (its estimate "
        "diverges: e.g. 1 in every case on one side)";
    return fit;
  }
  const double df = static_cast<double>(n) - 2.0;
  fit.dispersion = df > 0.0 ? glm.pearson_chi2 / df : 1.0;
  fit.common.coefficients = glm.coefficients;
  fit.common.covariance = glm.covariance * fit.dispersion;
  fit.common.deviance = glm.deviance;
  fit.common.goodness_of_fit = {{"pearson-dispersion", fit.dispersion, df, std::nullopt}};
  return fit;
}

}  // namespace

std::vector<RetainedFractionFit> fit_retained_fractions(const CaseOutcomeTable& table,
                                                        const std::vector<CaseGroup>& groups,
                                                        const CorrelationRequest& request) {
  std::vector<RetainedFractionFit> fits;
  if (request.speed_axis.empty()) return fits;
  for (const CaseGroup& group : groups) fits.push_back(fit_one(table, group, request));
  return fits;
}

BandPoint RetainedFractionFit::mean_fraction(double speed) const {
  const Eigen::Vector2d x(1.0, std::log(speed));
  const double eta = x.dot(common.coefficients);
  const double half_width = kZ95 * std::sqrt(std::max(0.0, x.dot(common.covariance * x)));
  return {logistic(eta), logistic(eta - half_width), logistic(eta + half_width)};
}

}  // namespace aerobreak
