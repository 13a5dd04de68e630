#include "orchestrator/fitting/binomial_glm.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace aerobreak {

double log1p_exp(double x) { return x > 0.0 ? x + std::log1p(std::exp(-x)) : std::log1p(std::exp(x)); }

double logistic(double x) {
  if (x >= 0.0) return 1.0 / (1.0 + std::exp(-x));
  const double e = std::exp(x);
  return e / (1.0 + e);
}

namespace {

// The pieces of one Newton step, evaluated at one delta.
struct Evaluation {
  Eigen::VectorXd mu;
  Eigen::VectorXd residual;  // y - n mu, plus h (1/2 - mu) under the Firth penalty
  Eigen::VectorXd weights;   // n mu (1 - mu)
  double objective = 0.0;
  Eigen::VectorXd score;        // of delta
  Eigen::MatrixXd information;  // of delta
};

// The problem in terms of delta: eta = offset + design * delta (design = X map, offset = data
// offset + X shift).
struct Problem {
  const BinomialData& data;
  Eigen::MatrixXd free_design;
  Eigen::VectorXd offset;
  Penalty penalty;
};

Problem make_problem(const BinomialData& data, const GlmOptions& options) {
  const auto n = data.design.rows();
  if (data.trials.size() != n || data.successes.size() != n || (data.offset.size() != 0 && data.offset.size() != n))
    throw std::invalid_argument("binomial data: rows of unequal length");
  Problem problem{data, data.design, data.offset.size() ? data.offset : Eigen::VectorXd::Zero(n), options.penalty};
  if (options.constraint) {
    problem.free_design = data.design * options.constraint->map;
    problem.offset += data.design * options.constraint->shift;
  }
  return problem;
}

// sum y eta - n log(1 + exp(eta)): the log-likelihood without its log C(n, y) terms.
double log_likelihood_kernel(const BinomialData& data, const Eigen::VectorXd& eta) {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < eta.size(); ++i) sum += data.successes[i] * eta[i] - data.trials[i] * log1p_exp(eta[i]);
  return sum;
}

// mu_i = logistic(eta_i) and the log-likelihood kernel with one exponential per row:
// e = exp(-|eta|), log(1 + exp(eta)) = max(eta, 0) + log1p(e).
double probabilities_and_kernel(const BinomialData& data, const Eigen::VectorXd& eta, Eigen::VectorXd& mu) {
  mu.resize(eta.size());
  double sum = 0.0;
  for (Eigen::Index i = 0; i < eta.size(); ++i) {
    // Beyond |eta| = 700 exp underflows (slowly, through libm's error path); 0 is exact to rounding.
    const double e = std::abs(eta[i]) < 700.0 ? std::exp(-std::abs(eta[i])) : 0.0;
    mu[i] = eta[i] >= 0.0 ? 1.0 / (1.0 + e) : e / (1.0 + e);
    sum += data.successes[i] * eta[i] - data.trials[i] * (std::max(eta[i], 0.0) + std::log1p(e));
  }
  return sum;
}

// Firth's hat values h_i = w_i x_i' (X'WX)^-1 x_i on the full design, and log |X'WX|.
double firth_terms(const BinomialData& data, const Eigen::VectorXd& weights, Eigen::VectorXd& hat) {
  const Eigen::MatrixXd root_weighted = data.design.array().colwise() * weights.array().sqrt();
  const Eigen::MatrixXd information = root_weighted.transpose() * root_weighted;
  const Eigen::LLT<Eigen::MatrixXd> cholesky(information);
  if (cholesky.info() != Eigen::Success) {
    hat = Eigen::VectorXd::Zero(weights.size());
    return -std::numeric_limits<double>::infinity();
  }
  const Eigen::MatrixXd solved = cholesky.matrixL().solve(root_weighted.transpose());
  hat = solved.colwise().squaredNorm().transpose();
  return 2.0 * cholesky.matrixL().toDenseMatrix().diagonal().array().log().sum();
}

Evaluation evaluate(const Problem& problem, const Eigen::VectorXd& delta) {
  const Eigen::VectorXd eta = problem.offset + problem.free_design * delta;
  Evaluation e;
  e.objective = probabilities_and_kernel(problem.data, eta, e.mu);
  e.weights = problem.data.trials.array() * e.mu.array() * (1.0 - e.mu.array());
  e.residual = problem.data.successes - problem.data.trials.cwiseProduct(e.mu);
  if (problem.penalty == Penalty::firth) {
    // Modified score (Firth 1993, eq 2 for the logit link): y - n mu + h (1/2 - mu).
    Eigen::VectorXd hat;
    e.objective += 0.5 * firth_terms(problem.data, e.weights, hat);
    e.residual += hat.cwiseProduct((0.5 - e.mu.array()).matrix());
  }
  e.score = problem.free_design.transpose() * e.residual;
  const Eigen::MatrixXd root_weighted = problem.free_design.array().colwise() * e.weights.array().sqrt();
  e.information = root_weighted.transpose() * root_weighted;
  return e;
}

bool small_step(const Eigen::VectorXd& step, const Eigen::VectorXd& delta, double tolerance) {
  for (Eigen::Index j = 0; j < step.size(); ++j)
    if (std::abs(step[j]) > tolerance * (1.0 + std::abs(delta[j]))) return false;
  return true;
}

// 0 log 0 = 0.
double x_log_x_over(double x, double y) { return x > 0.0 ? x * std::log(x / y) : 0.0; }

void finish(const Problem& problem, const GlmOptions& options, const Evaluation& at, GlmFit& fit) {
  const BinomialData& data = problem.data;
  fit.coefficients =
      options.constraint ? Eigen::VectorXd(options.constraint->map * fit.free + options.constraint->shift) : fit.free;
  fit.objective = at.objective;
  fit.full_score = data.design.transpose() * at.residual;
  if (!options.statistics) return;
  fit.covariance = at.information.ldlt().solve(Eigen::MatrixXd::Identity(fit.free.size(), fit.free.size()));
  double log_binomial = 0.0;
  fit.deviance = 0.0;
  fit.pearson_chi2 = 0.0;
  for (Eigen::Index i = 0; i < data.trials.size(); ++i) {
    const double n = data.trials[i], y = data.successes[i], mean = n * at.mu[i];
    log_binomial += std::lgamma(n + 1.0) - std::lgamma(y + 1.0) - std::lgamma(n - y + 1.0);
    fit.deviance += 2.0 * (x_log_x_over(y, mean) + x_log_x_over(n - y, n - mean));
    if (at.weights[i] > 0.0) fit.pearson_chi2 += (y - mean) * (y - mean) / at.weights[i];
  }
  const Eigen::VectorXd eta = problem.offset + problem.free_design * fit.free;
  fit.log_likelihood = log_likelihood_kernel(data, eta) + log_binomial;
}

}  // namespace

GlmFit fit_binomial(const BinomialData& data, const GlmOptions& options) {
  const Problem problem = make_problem(data, options);
  GlmFit fit;
  fit.free = options.start ? *options.start : Eigen::VectorXd::Zero(problem.free_design.cols());
  fit.last_step = Eigen::VectorXd::Zero(fit.free.size());
  Evaluation current = evaluate(problem, fit.free);
  while (fit.iterations < options.max_iterations && !fit.converged) {
    ++fit.iterations;
    Eigen::VectorXd step = current.information.ldlt().solve(current.score);
    if (!step.allFinite()) break;
    // Step halving: never accept a step that lowers the objective (beyond rounding).
    bool accepted = false;
    for (int halvings = 0; halvings < 40 && !accepted; ++halvings, step *= 0.5) {
      Evaluation next = evaluate(problem, fit.free + step);
      if (std::isfinite(next.objective) && next.objective >= current.objective - 1e-12 * std::abs(current.objective)) {
        fit.converged = small_step(step, fit.free, options.tolerance);
        fit.free += step;
        fit.last_step = step;
        current = std::move(next);
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  finish(problem, options, current, fit);
  return fit;
}

Eigen::VectorXd fitted_probabilities(const BinomialData& data, const Eigen::VectorXd& beta) {
  Eigen::VectorXd eta = data.design * beta;
  if (data.offset.size()) eta += data.offset;
  return eta.unaryExpr([](double x) { return logistic(x); });
}

}  // namespace aerobreak
