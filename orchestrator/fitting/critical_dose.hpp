#pragma once
#include <Eigen/Dense>
#include <optional>
#include <string>

#include "orchestrator/fitting/binomial_glm.hpp"

namespace aerobreak {

// The dose (log impact speed, log energy per contact) at which a logistic model's probability
// crosses `level`, at a point of the other covariates: theta with c(theta)' beta = logit(level),
// c(theta) = reference + theta e_dose, where column 0 of the design is the intercept. Its 95 %
// interval is the profile likelihood interval (Venzon & Moolgavkar, Appl. Statist. 37 (1988) 87;
// for effective doses, Morgan, Analysis of Quantal Response Data, 1992, sec. 4.2): every theta whose
// constrained maximum of the (penalised) log-likelihood lies within chi^2_1(0.95)/2 = 1.92 of the
// overall maximum. Unlike the delta method it follows the skew of the likelihood; unlike Fieller's
// it needs no normal approximation of beta. Under the Firth penalty it is the profile penalised
// likelihood interval of Heinze & Schemper (2002), which stays bounded under separation.
struct CriticalDose {
  double level = 0.5;
  std::optional<double> estimate;  // theta-hat; none when the slope is zero
  std::optional<double> lower;     // none: the data do not bound it on that side within `search`
  std::optional<double> upper;
};

struct CriticalDoseRequest {
  Eigen::VectorXd reference;  // c(0): 1 for the intercept, covariate values, 0 at the dose
  Eigen::Index dose_column = 1;
  double level = 0.5;
  double search_low = 0.0;  // theta range searched for the interval's ends
  double search_high = 0.0;
  Penalty penalty = Penalty::none;
};

CriticalDose critical_dose(const BinomialData& data, const GlmFit& fit, const CriticalDoseRequest& request);

// The same theta-hat with the delta-method interval theta +- 1.96 SE(theta), SE from the gradient of
// (logit(level) - c' beta) / beta_dose and the covariance of beta: for the pooled models, whose
// critical values are wanted at every group's covariates (many profiles over every case).
CriticalDose critical_dose_delta(const GlmFit& fit, const CriticalDoseRequest& request);

// The 0.95 quantile of chi^2 with one degree of freedom (= 1.959964^2).
inline constexpr double kChiSquare1At95 = 3.841458820694124;

}  // namespace aerobreak
