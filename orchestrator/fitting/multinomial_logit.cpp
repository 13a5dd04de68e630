#include "orchestrator/fitting/multinomial_logit.hpp"

#include <cmath>
#include <map>

namespace aerobreak {
namespace {

// Category probabilities at eta = (0, eta_1, eta_2) (baseline first).
Eigen::Vector3d softmax(double eta1, double eta2) {
  const double top = std::max({0.0, eta1, eta2});
  Eigen::Vector3d e(std::exp(-top), std::exp(eta1 - top), std::exp(eta2 - top));
  return e / e.sum();
}

struct Step {
  double log_likelihood = 0.0;
  Eigen::Vector4d score = Eigen::Vector4d::Zero();
  Eigen::Matrix4d information = Eigen::Matrix4d::Zero();
};

// theta = (a_1, b_1, a_2, b_2).
Step evaluate(const MultinomialFit& fit, const Eigen::Vector4d& theta) {
  Step step;
  for (std::size_t i = 0; i < fit.doses.size(); ++i) {
    const Eigen::Vector2d x(1.0, std::log(fit.doses[i]));
    const Eigen::Vector3d pi = softmax(theta.segment<2>(0).dot(x), theta.segment<2>(2).dot(x));
    const auto& y = fit.counts[i];
    const double n = y[0] + y[1] + y[2];
    for (int k = 0; k < 3; ++k) step.log_likelihood += y[static_cast<std::size_t>(k)] * std::log(pi[k]);
    for (int k = 0; k < 2; ++k) {
      step.score.segment<2>(2 * k) += (y[static_cast<std::size_t>(k + 1)] - n * pi[k + 1]) * x;
      for (int l = 0; l < 2; ++l)
        step.information.block<2, 2>(2 * k, 2 * l) +=
            n * pi[k + 1] * ((k == l ? 1.0 : 0.0) - pi[l + 1]) * x * x.transpose();
    }
  }
  return step;
}

void newton(MultinomialFit& fit) {
  Eigen::Vector4d theta = Eigen::Vector4d::Zero();
  Step current = evaluate(fit, theta);
  bool converged = false;
  for (int iteration = 0; iteration < 40 && !converged; ++iteration) {
    Eigen::Vector4d delta = current.information.ldlt().solve(current.score);
    if (!delta.allFinite()) break;
    for (int halving = 0; halving < 40; ++halving, delta *= 0.5) {
      const Step next = evaluate(fit, theta + delta);
      if (next.log_likelihood >= current.log_likelihood - 1e-12 * std::abs(current.log_likelihood)) {
        converged = (delta.array().abs() <= 1e-10 * (1.0 + theta.array().abs())).all();
        theta += delta;
        current = next;
        break;
      }
    }
  }
  // Under separation the coefficients run off and the steps never become small.
  if (!converged) {
    fit.common.status = FitStatus::separation;
    fit.common.detail =
        "the maximum-likelihood estimate does not exist (the outcomes are separated along the speed): "
        "see the binomial fits of this group";
    return;
  }
  fit.common.coefficients = theta;
  fit.common.covariance = current.information.inverse();
  fit.common.log_likelihood = current.log_likelihood;
}

}  // namespace

MultinomialFit fit_multinomial(const std::vector<double>& doses, const std::vector<std::vector<double>>& counts) {
  MultinomialFit fit;
  fit.common.kind = "multinomial";
  fit.dose = "impact_speed";
  fit.categories = {ImpactOutcome::stick, ImpactOutcome::bounce, ImpactOutcome::break_up};
  fit.common.parameters = {"bounce: intercept", "bounce: log(impact_speed)", "break-up: intercept",
                           "break-up: log(impact_speed)"};
  fit.doses = doses;
  fit.counts = counts;
  fit.common.groups = doses.size();
  if (doses.size() < 2) {
    fit.common.status = FitStatus::insufficient_data;
    fit.common.detail = "too few points: " + std::to_string(doses.size()) + " distinct speed(s)";
    return fit;
  }
  fit.common.validity = {{"impact_speed", doses.front(), doses.back()}};
  newton(fit);
  return fit;
}

std::array<BandPoint, 3> MultinomialFit::probabilities(double dose_value) const {
  const Eigen::Vector2d x(1.0, std::log(dose_value));
  const Eigen::Vector4d& theta = common.coefficients;
  const Eigen::Vector3d pi = softmax(theta.segment<2>(0).dot(x), theta.segment<2>(2).dot(x));
  std::array<BandPoint, 3> bands;
  for (int c = 0; c < 3; ++c) {
    // d pi_c / d theta_(k,.) = pi_c (delta_ck - pi_k) x, k = 1, 2 (delta method).
    Eigen::Vector4d gradient;
    for (int k = 0; k < 2; ++k) gradient.segment<2>(2 * k) = pi[c] * ((c == k + 1 ? 1.0 : 0.0) - pi[k + 1]) * x;
    const double half_width = kZ95 * std::sqrt(std::max(0.0, gradient.dot(common.covariance * gradient)));
    bands[static_cast<std::size_t>(c)] = {pi[c], std::max(0.0, pi[c] - half_width), std::min(1.0, pi[c] + half_width)};
  }
  return bands;
}

std::vector<MultinomialFit> fit_multinomial_models(const CaseOutcomeTable& table, const std::vector<CaseGroup>& groups,
                                                   const CorrelationRequest& request) {
  std::vector<MultinomialFit> fits;
  if (request.speed_axis.empty()) return fits;
  for (const CaseGroup& group : groups) {
    std::map<double, std::vector<double>> by_speed;
    std::array<bool, 3> seen{};
    std::size_t small_strain = 0, cases = 0;
    for (const CaseOutcome* c : determined_cases(group.cases)) {
      const double speed = axis_number(table.grid_points[c->grid_point], request.speed_axis);
      if (!(speed > 0.0)) continue;
      auto& row = by_speed.try_emplace(speed, std::vector<double>(3, 0.0)).first->second;
      row[static_cast<std::size_t>(c->outcome)] += 1.0;
      seen[static_cast<std::size_t>(c->outcome)] = true;
      small_strain += c->small_strain_exceeded ? 1 : 0;
      ++cases;
    }
    if (!(seen[0] && seen[1] && seen[2])) continue;
    std::vector<double> doses;
    std::vector<std::vector<double>> counts;
    for (const auto& [speed, row] : by_speed) {
      doses.push_back(speed);
      counts.push_back(row);
    }
    MultinomialFit fit = fit_multinomial(doses, counts);
    fit.common.name = "outcomes.speed." + group.label;
    fit.common.group = group.axes;
    fit.common.cases = cases;
    fit.common.small_strain_cases = small_strain;
    fits.push_back(std::move(fit));
  }
  return fits;
}

}  // namespace aerobreak
