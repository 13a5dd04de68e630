#include "orchestrator/fitting/critical_dose.hpp"

#include <algorithm>
#include <cmath>

#include "orchestrator/fitting/proportion.hpp"

namespace aerobreak {
namespace {

double logit(double p) { return std::log(p / (1.0 - p)); }

// The constrained model of one theta: beta_0 = logit(level) - sum_{k>0} c_k(theta) beta_k, the
// other coefficients free.
LinearConstraint constraint_at(const CriticalDoseRequest& request, double theta) {
  const Eigen::Index p = request.reference.size();
  LinearConstraint constraint{Eigen::MatrixXd::Zero(p, p - 1), Eigen::VectorXd::Zero(p)};
  Eigen::VectorXd c = request.reference;
  c[request.dose_column] = theta;
  constraint.map.row(0) = -c.tail(p - 1).transpose();
  constraint.map.bottomRows(p - 1).setIdentity();
  constraint.shift[0] = logit(request.level);
  return constraint;
}

struct GapValue {
  double value = 0.0;
  double slope = 0.0;
};

// Twice the drop of the (penalised) log-likelihood when theta is imposed, minus chi^2_1(0.95):
// negative inside the interval; and its derivative in theta, which the constrained fit gives for
// free (envelope theorem: d l_p / d theta = dl/d beta_0 x d beta_0 / d theta = -U_0 beta_dose).
// Warm-starts from the last constrained fit.
class ProfileGap {
 public:
  ProfileGap(const BinomialData& data, const GlmFit& fit, const CriticalDoseRequest& request)
      : data_(data),
        request_(request),
        best_(fit.objective),
        start_(fit.coefficients.tail(fit.coefficients.size() - 1)) {}

  GapValue operator()(double theta) {
    const LinearConstraint constraint = constraint_at(request_, theta);
    GlmOptions options;
    options.penalty = request_.penalty;
    options.constraint = &constraint;
    options.start = &start_;
    options.max_iterations = 100;
    options.statistics = false;
    // The gap is quadratic in the error of the inner optimum: 1e-7 there is 1e-14 in the gap.
    options.tolerance = 1e-7;
    const GlmFit constrained = fit_binomial(data_, options);
    if (constrained.free.allFinite()) start_ = constrained.free;
    return {2.0 * (best_ - constrained.objective) - kChiSquare1At95,
            2.0 * constrained.full_score[0] * constrained.coefficients[request_.dose_column]};
  }

 private:
  const BinomialData& data_;
  const CriticalDoseRequest& request_;
  double best_;
  Eigen::VectorXd start_;
};

// The root of the gap between the estimate (gap -3.84) and `limit`, by Newton steps from `guess`
// kept inside the bracket once one is known (bisection when a step leaves it), and doubling
// outward until the gap turns positive. nullopt when it is still negative at the limit.
std::optional<double> interval_end(ProfileGap& gap, double estimate, double guess, double limit) {
  const double direction = limit > estimate ? 1.0 : -1.0;
  const auto beyond = [direction](double a, double b) { return direction * (a - b) > 0.0; };  // a further out than b
  double inside = estimate;
  std::optional<double> outside;
  double theta = beyond(guess, limit) ? limit : guess;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const GapValue g = gap(theta);
    if (!std::isfinite(g.value)) return std::nullopt;
    if (g.value > 0.0)
      outside = theta;
    else
      inside = theta;
    if (std::abs(g.value) < 1e-10 || (outside && std::abs(*outside - inside) < 1e-12 * (1.0 + std::abs(theta))))
      return theta;
    if (!outside && theta == limit) return std::nullopt;
    double next = theta - g.value / g.slope;
    if (outside) {
      if (!(beyond(next, inside) && beyond(*outside, next))) next = 0.5 * (inside + *outside);
    } else if (!std::isfinite(next) || !beyond(next, theta)) {
      next = theta + (theta - estimate);  // doubling the distance from the estimate
    }
    theta = beyond(next, limit) ? limit : next;
  }
  return std::nullopt;
}

// The delta-method standard error of theta-hat: gradient of (logit(level) - c' beta) / beta_dose.
double delta_standard_error(const GlmFit& fit, const Eigen::VectorXd& c, Eigen::Index dose, double theta) {
  const Eigen::VectorXd& beta = fit.coefficients;
  Eigen::VectorXd gradient = -c / beta[dose];
  gradient[dose] = -theta / beta[dose];
  return std::sqrt(std::max(0.0, gradient.dot(fit.covariance * gradient)));
}

}  // namespace

CriticalDose critical_dose_delta(const GlmFit& fit, const CriticalDoseRequest& request) {
  CriticalDose result;
  result.level = request.level;
  const double slope = fit.coefficients[request.dose_column];
  if (slope == 0.0 || !fit.coefficients.allFinite()) return result;
  Eigen::VectorXd c = request.reference;
  c[request.dose_column] = 0.0;
  const double theta = (logit(request.level) - c.dot(fit.coefficients)) / slope;
  const double half_width = kZ95 * delta_standard_error(fit, c, request.dose_column, theta);
  result.estimate = theta;
  if (std::isfinite(half_width)) {
    result.lower = theta - half_width;
    result.upper = theta + half_width;
  }
  return result;
}

CriticalDose critical_dose(const BinomialData& data, const GlmFit& fit, const CriticalDoseRequest& request) {
  CriticalDose result;
  result.level = request.level;
  const Eigen::VectorXd& beta = fit.coefficients;
  const double slope = beta[request.dose_column];
  if (slope == 0.0 || !beta.allFinite()) return result;
  Eigen::VectorXd c = request.reference;
  c[request.dose_column] = 0.0;
  const double theta = (logit(request.level) - c.dot(beta)) / slope;
  result.estimate = theta;
  // The Newton search starts at the delta-method ends theta +- 1.96 SE (at least 1e-3 away).
  double step = kZ95 * delta_standard_error(fit, c, request.dose_column, theta);
  if (!std::isfinite(step) || step < 1e-3) step = 1e-3;
  ProfileGap gap(data, fit, request);
  if (theta > request.search_low) result.lower = interval_end(gap, theta, theta - step, request.search_low);
  if (theta < request.search_high) result.upper = interval_end(gap, theta, theta + step, request.search_high);
  return result;
}

}  // namespace aerobreak
