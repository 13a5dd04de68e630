#include "orchestrator/fitting/goodness_of_fit.hpp"

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <numeric>

namespace aerobreak {

std::optional<double> chi_square_upper_tail(double x, double df) {
  if (!(df > 0.0)) return std::nullopt;
  return boost::math::gamma_q(0.5 * df, 0.5 * std::max(0.0, x));
}

namespace {

GoodnessOfFit hosmer_lemeshow(const BinomialData& data, const GlmFit& fit) {
  const Eigen::VectorXd mu = fitted_probabilities(data, fit.coefficients);
  std::vector<Eigen::Index> order(static_cast<std::size_t>(mu.size()));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return mu[a] < mu[b]; });
  constexpr std::size_t kGroups = 10;
  double statistic = 0.0;
  for (std::size_t g = 0; g < kGroups; ++g) {
    const std::size_t begin = g * order.size() / kGroups, end = (g + 1) * order.size() / kGroups;
    double observed = 0.0, expected = 0.0, trials = 0.0;
    for (std::size_t r = begin; r < end; ++r) {
      observed += data.successes[order[r]];
      expected += data.trials[order[r]] * mu[order[r]];
      trials += data.trials[order[r]];
    }
    const double variance = expected * (1.0 - expected / std::max(trials, 1.0));
    if (variance > 0.0) statistic += (observed - expected) * (observed - expected) / variance;
  }
  return {"hosmer-lemeshow", statistic, kGroups - 2.0, chi_square_upper_tail(statistic, kGroups - 2.0)};
}

}  // namespace

std::vector<GoodnessOfFit> binomial_goodness_of_fit(const BinomialData& data, const GlmFit& fit,
                                                    std::size_t parameters) {
  const bool grouped = (data.trials.array() > 1.0).any();
  if (!grouped) {
    if (data.trials.size() < 20) return {};
    return {hosmer_lemeshow(data, fit)};
  }
  const double df = static_cast<double>(data.trials.size()) - static_cast<double>(parameters);
  return {{"deviance", fit.deviance, df, chi_square_upper_tail(fit.deviance, df)},
          {"pearson", fit.pearson_chi2, df, chi_square_upper_tail(fit.pearson_chi2, df)}};
}

}  // namespace aerobreak
