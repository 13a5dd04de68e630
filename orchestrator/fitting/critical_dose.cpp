#include "orchestrator/fitting/critical_dose.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <stdexcept>

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

// Twice the drop of the (penalised) log-likelihood when theta is imposed, minus chi^2_1(0.95):
// negative inside the interval. Warm-starts from the last constrained fit.
class ProfileGap {
 public:
  ProfileGap(const BinomialData& data, const GlmFit& fit, const CriticalDoseRequest& request)
      : data_(data), request_(request), best_(fit.objective), start_(fit.coefficients.tail(fit.coefficients.size() - 1)) {}

  double operator()(double theta) {
    const LinearConstraint constraint = constraint_at(request_, theta);
    GlmOptions options;
    options.penalty = request_.penalty;
    options.constraint = &constraint;
    options.start = &start_;
    options.max_iterations = 100;
    const GlmFit constrained = fit_binomial(data_, options);
    if (constrained.free.allFinite()) start_ = constrained.free;
    return 2.0 * (best_ - constrained.objective) - kChiSquare1At95;
  }

 private:
  const BinomialData& data_;
  const CriticalDoseRequest& request_;
  double best_;
  Eigen::VectorXd start_;
};

// Walks from the estimate towards `limit` in doubling steps until the gap turns positive, then
// solves gap = 0 between the last two points (TOMS 748). nullopt when the limit comes first.
std::optional<double> interval_end(ProfileGap& gap, double estimate, double first_step, double limit) {
  const double direction = limit > estimate ? 1.0 : -1.0;
  double inside = estimate, g_inside = -kChiSquare1At95, step = first_step;
  for (;;) {
    double probe = estimate + direction * step;
    const bool last = direction * (probe - limit) >= 0.0;
    if (last) probe = limit;
    const double value = gap(probe);
    if (value > 0.0) {
      std::uintmax_t iterations = 200;
      const auto tolerance = [](double a, double b) { return std::abs(a - b) <= 1e-11 * (1.0 + std::abs(a)); };
      try {
        const auto [a, b] = direction > 0.0
                                ? boost::math::tools::toms748_solve(gap, inside, probe, g_inside, value, tolerance, iterations)
                                : boost::math::tools::toms748_solve(gap, probe, inside, value, g_inside, tolerance, iterations);
        return 0.5 * (a + b);
      } catch (const std::exception&) {
        // A profile that is not monotone between the two points (a constrained fit that did not
        // converge): the end is reported as unknown rather than guessed.
        return std::nullopt;
      }
    }
    if (last) return std::nullopt;
    inside = probe;
    g_inside = value;
    step *= 2.0;
  }
}

}  // namespace

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
  // A first step of a tenth of the searched width (at least 1e-3) brackets most ends in a few doublings.
  const double first_step = std::max(1e-3, 0.1 * (request.search_high - request.search_low));
  ProfileGap gap(data, fit, request);
  if (theta > request.search_low) result.lower = interval_end(gap, theta, first_step, request.search_low);
  if (theta < request.search_high) result.upper = interval_end(gap, theta, first_step, request.search_high);
  return result;
}

}  // namespace aerobreak
