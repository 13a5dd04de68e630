#include "orchestrator/fitting/logistic_prediction.hpp"

#include <cmath>
#include <limits>

namespace aerobreak {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool in_range(const InputRange& range, double value) {
  return value >= range.min * (1.0 - 1e-12) && value <= range.max * (1.0 + 1e-12);
}

// The observed 0 or 1 of a fit whose outcome never (always) occurs, with the Wilson interval of all its cases.
BandPoint observed_share(const LogisticFit& fit) {
  const auto trials = static_cast<std::size_t>(fit.data.trials.sum());
  const auto successes = static_cast<std::size_t>(fit.data.successes.sum());
  const auto wilson = wilson_interval(successes, trials);
  if (!wilson) return {kNaN, kNaN, kNaN};
  return {wilson->probability, wilson->lower, wilson->upper};
}

}  // namespace

bool inside_validity(const LogisticFit& fit, double dose, const Eigen::VectorXd& covariates) {
  if (fit.common.validity.empty()) return false;
  for (const auto& range : fit.common.validity) {
    if (range.input == fit.dose) {
      if (!in_range(range, dose)) return false;
      continue;
    }
    for (std::size_t k = 0; k < fit.covariates.size(); ++k)
      if (fit.covariates[k].axis == range.input && (static_cast<Eigen::Index>(k) >= covariates.size() ||
                                                    !in_range(range, covariates[static_cast<Eigen::Index>(k)])))
        return false;
  }
  return true;
}

Prediction predict(const LogisticFit& fit, double dose, const Eigen::VectorXd& covariates) {
  Prediction prediction{{kNaN, kNaN, kNaN}, PredictionSource::none, inside_validity(fit, dose, covariates)};
  const bool fitted = fit.common.coefficients.size() == static_cast<Eigen::Index>(2 + fit.covariates.size());
  switch (fit.common.status) {
    case FitStatus::ok:
      if (!fitted) return prediction;
      prediction.source = PredictionSource::maximum_likelihood;
      prediction.band = fit.probability(dose, covariates);
      return prediction;
    case FitStatus::separation:
      if (!fitted || !fit.covariates.empty()) return prediction;
      prediction.source = PredictionSource::firth;
      prediction.band = fit.probability(dose, covariates);
      return prediction;
    case FitStatus::no_transition:
      prediction.source = PredictionSource::no_transition;
      prediction.band = observed_share(fit);
      return prediction;
    case FitStatus::insufficient_data:
    case FitStatus::not_converged:
      break;
  }
  return prediction;
}

}  // namespace aerobreak
