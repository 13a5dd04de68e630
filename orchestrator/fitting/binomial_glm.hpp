#pragma once
#include <Eigen/Dense>

namespace aerobreak {

// Grouped binomial data for a logistic regression logit(mu_i) = offset_i + x_i' beta (McCullagh &
// Nelder, Generalized Linear Models, 2nd ed., ch. 4): row i has n_i > 0 trials and y_i in [0, n_i]
// successes. Fractional y_i with n_i = 1 (a mass fraction) make it the fractional logit of Papke &
// Wooldridge (J. Appl. Econometrics 11 (1996) 619), a quasi-binomial model: same estimating
// equations, the dispersion estimated afterwards.
struct BinomialData {
  Eigen::MatrixXd design;     // n x p, rows x_i'
  Eigen::VectorXd trials;     // n_i
  Eigen::VectorXd successes;  // y_i
  Eigen::VectorXd offset;     // empty: none
};

// beta = map * delta + shift: the fit runs over delta only. The profile likelihood of a critical
// dose (critical_dose.hpp) fixes one linear combination of beta this way.
struct LinearConstraint {
  Eigen::MatrixXd map;    // p x q
  Eigen::VectorXd shift;  // p
};

// Firth (Biometrika 80 (1993) 27): the likelihood times the Jeffreys prior |I(beta)|^(1/2). Its
// estimate is finite under separation, where maximum likelihood has none (Heinze & Schemper,
// Statist. Med. 21 (2002) 2409).
enum class Penalty { none, firth };

struct GlmFit {
  Eigen::VectorXd coefficients;  // beta
  Eigen::VectorXd free;          // delta (= beta without a constraint)
  Eigen::MatrixXd covariance;    // inverse Fisher information of delta at the estimate (unit dispersion)
  double log_likelihood = 0.0;   // binomial log-likelihood with its log C(n, y) terms, as R's logLik
  double objective = 0.0;        // log-likelihood, plus 0.5 log |I(beta)| under the Firth penalty
  double deviance = 0.0;         // 2 (saturated - fitted) log-likelihood
  double pearson_chi2 = 0.0;     // sum (y - n mu)^2 / (n mu (1 - mu))
  Eigen::VectorXd full_score;    // X' (y - n mu [+ h (1/2 - mu)]): the (modified) score of beta at the estimate
  Eigen::VectorXd last_step;     // the last Newton step in delta: a separating direction when it diverges
  int iterations = 0;
  bool converged = false;
};

struct GlmOptions {
  Penalty penalty = Penalty::none;
  const LinearConstraint* constraint = nullptr;
  const Eigen::VectorXd* start = nullptr;  // delta to start from (warm start); zeros otherwise
  int max_iterations = 30;
  double tolerance = 1e-10;  // on each step component, relative to 1 + |delta_j|
  bool statistics = true;    // false: skip the covariance, deviance, Pearson X^2 and log-likelihood (profiles)
};

// Newton-Raphson on the (penalised) log-likelihood with step halving: for the canonical logit link
// this is iteratively reweighted least squares (Fisher scoring = Newton). Converged when every
// step component is below tolerance x (1 + |delta_j|).
GlmFit fit_binomial(const BinomialData& data, const GlmOptions& options = {});

// Fitted probabilities mu_i of the data's rows at coefficients beta.
Eigen::VectorXd fitted_probabilities(const BinomialData& data, const Eigen::VectorXd& beta);

// log(1 + exp(x)) without overflow, and the logistic function 1 / (1 + exp(-x)).
double log1p_exp(double x);
double logistic(double x);

}  // namespace aerobreak
