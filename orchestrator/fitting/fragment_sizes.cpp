#include "orchestrator/fitting/fragment_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "orchestrator/fitting/case_groups.hpp"

namespace aerobreak {
namespace {

using Histogram = std::vector<std::pair<std::int64_t, std::size_t>>;

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// ln P(s) of the power law on 1..N for every s in 1..N.
std::vector<double> power_law_log_pmf(double tau, std::int64_t n) {
  std::vector<double> log_pmf(static_cast<std::size_t>(n));
  double norm = 0.0;
  for (std::int64_t s = 1; s <= n; ++s) norm += std::pow(static_cast<double>(s), -tau);
  for (std::int64_t s = 1; s <= n; ++s)
    log_pmf[static_cast<std::size_t>(s - 1)] = -tau * std::log(static_cast<double>(s)) - std::log(norm);
  return log_pmf;
}

// Newton on tau: d lnL/d tau = n <ln s>_tau - sum ln s_i, d2 = -n Var_tau(ln s).
void fit_power_law(FragmentSizeFit& fit, double count, double sum_log) {
  double tau = 2.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    double h0 = 0.0, h1 = 0.0, h2 = 0.0;
    for (std::int64_t s = 1; s <= fit.largest_size; ++s) {
      const double l = std::log(static_cast<double>(s)), weight = std::pow(static_cast<double>(s), -tau);
      h0 += weight;
      h1 += l * weight;
      h2 += l * l * weight;
    }
    const double mean = h1 / h0, variance = h2 / h0 - mean * mean;
    const double step = (count * mean - sum_log) / (count * variance);
    fit.exponent_standard_error = 1.0 / std::sqrt(count * variance);
    tau += std::clamp(step, -2.0, 2.0);
    if (std::abs(step) < 1e-12 * (1.0 + std::abs(tau))) break;
  }
  fit.exponent = tau;
}

double lognormal_log_likelihood(const Histogram& histogram, std::int64_t n, double mu, double sigma) {
  const auto cdf = [&](double s) { return normal_cdf((std::log(s) - mu) / sigma); };
  const double norm = cdf(static_cast<double>(n) + 0.5) - cdf(0.5);
  double sum = 0.0;
  for (const auto& [size, count] : histogram) {
    const double mass = (cdf(static_cast<double>(size) + 0.5) - cdf(static_cast<double>(size) - 0.5)) / norm;
    sum += static_cast<double>(count) * std::log(std::max(mass, 1e-300));
  }
  return sum;
}

// Newton on (mu, ln sigma) with central differences and step halving.
void fit_lognormal(FragmentSizeFit& fit, double mean_log, double sd_log) {
  Eigen::Vector2d theta(mean_log, std::log(std::max(sd_log, 0.1)));
  const auto f = [&](const Eigen::Vector2d& t) {
    return lognormal_log_likelihood(fit.histogram, fit.largest_size, t[0], std::exp(t[1]));
  };
  const double h = 1e-4;
  Eigen::Matrix2d hessian;
  for (int iteration = 0; iteration < 100; ++iteration) {
    Eigen::Vector2d gradient;
    for (int i = 0; i < 2; ++i) {
      const Eigen::Vector2d e = Eigen::Vector2d::Unit(i) * h;
      gradient[i] = (f(theta + e) - f(theta - e)) / (2.0 * h);
      for (int j = 0; j < 2; ++j) {
        const Eigen::Vector2d d = Eigen::Vector2d::Unit(j) * h;
        hessian(i, j) = (f(theta + e + d) - f(theta + e - d) - f(theta - e + d) + f(theta - e - d)) / (4.0 * h * h);
      }
    }
    Eigen::Vector2d step = -hessian.ldlt().solve(gradient);
    if (!step.allFinite() || gradient.dot(step) <= 0.0) step = gradient * 1e-3;  // not a maximum: go uphill
    const double current = f(theta);
    for (int halving = 0; halving < 30 && !(f(theta + step) >= current); ++halving) step *= 0.5;
    theta += step;
    if (step.norm() < 1e-9) break;
  }
  fit.mu = theta[0];
  fit.sigma = std::exp(theta[1]);
  // Covariance of (mu, sigma) from that of (mu, ln sigma): Jacobian diag(1, sigma).
  const Eigen::Matrix2d jacobian = Eigen::Vector2d(1.0, fit.sigma).asDiagonal();
  fit.lognormal_covariance = jacobian * (-hessian).inverse() * jacobian.transpose();
  fit.lognormal_log_likelihood = f(theta);
}

// ln P(s) of the fitted lognormal for every s in 1..N.
std::vector<double> lognormal_log_pmf(const FragmentSizeFit& fit) {
  const auto cdf = [&](double s) { return normal_cdf((std::log(s) - fit.mu) / fit.sigma); };
  const double norm = cdf(static_cast<double>(fit.largest_size) + 0.5) - cdf(0.5);
  std::vector<double> log_pmf(static_cast<std::size_t>(fit.largest_size));
  for (std::int64_t s = 1; s <= fit.largest_size; ++s)
    log_pmf[static_cast<std::size_t>(s - 1)] =
        std::log(std::max((cdf(static_cast<double>(s) + 0.5) - cdf(static_cast<double>(s) - 0.5)) / norm, 1e-300));
  return log_pmf;
}

double ks_distance(const Histogram& histogram, double count, const std::vector<double>& log_pmf) {
  double data_cdf = 0.0, law_cdf = 0.0, distance = 0.0;
  auto bin = histogram.begin();
  for (std::size_t s = 1; s <= log_pmf.size(); ++s) {
    law_cdf += std::exp(log_pmf[s - 1]);
    if (bin != histogram.end() && bin->first == static_cast<std::int64_t>(s))
      data_cdf += static_cast<double>((bin++)->second) / count;
    distance = std::max(distance, std::abs(data_cdf - law_cdf));
  }
  return distance;
}

void compare(FragmentSizeFit& fit, double count, const std::vector<double>& power,
             const std::vector<double>& lognormal) {
  double sum = 0.0, squares = 0.0;
  fit.power_law_log_likelihood = 0.0;
  for (const auto& [size, n] : fit.histogram) {
    const auto i = static_cast<std::size_t>(size - 1);
    const double ratio = lognormal[i] - power[i];
    sum += static_cast<double>(n) * ratio;
    squares += static_cast<double>(n) * ratio * ratio;
    fit.power_law_log_likelihood += static_cast<double>(n) * power[i];
  }
  const double mean = sum / count, sd = std::sqrt(std::max(0.0, squares / count - mean * mean));
  fit.vuong_statistic = sd > 0.0 ? sum / (std::sqrt(count) * sd) : 0.0;
  fit.vuong_p_value = std::erfc(std::abs(fit.vuong_statistic) / std::sqrt(2.0));
  fit.power_law_ks = ks_distance(fit.histogram, count, power);
  fit.lognormal_ks = ks_distance(fit.histogram, count, lognormal);
}

}  // namespace

FragmentSizeFit fit_fragment_sizes(const std::vector<std::int64_t>& sizes, std::int64_t largest_size) {
  FragmentSizeFit fit;
  fit.common.kind = "fragment-sizes";
  fit.common.parameters = {"tau", "mu", "sigma"};
  std::map<std::int64_t, std::size_t> counts;
  double sum_log = 0.0, sum_log2 = 0.0;
  for (const auto s : sizes) {
    ++counts[s];
    sum_log += std::log(static_cast<double>(s));
    sum_log2 += std::log(static_cast<double>(s)) * std::log(static_cast<double>(s));
  }
  fit.histogram.assign(counts.begin(), counts.end());
  fit.largest_size = std::max(largest_size, counts.empty() ? std::int64_t{1} : counts.rbegin()->first);
  const double n = static_cast<double>(sizes.size());
  if (sizes.size() < 5 || counts.size() < 2) {
    fit.common.status = FitStatus::insufficient_data;
    fit.common.detail = "too few points: " + std::to_string(sizes.size()) + " re-entrained fragment(s) of " +
                        std::to_string(counts.size()) + " distinct size(s); a size distribution needs 5 and 2";
    return fit;
  }
  fit_power_law(fit, n, sum_log);
  const double mean_log = sum_log / n;
  fit_lognormal(fit, mean_log, std::sqrt(std::max(0.0, sum_log2 / n - mean_log * mean_log)));
  compare(fit, n, power_law_log_pmf(fit.exponent, fit.largest_size), lognormal_log_pmf(fit));
  fit.common.coefficients = Eigen::Vector3d(fit.exponent, fit.mu, fit.sigma);
  fit.common.covariance = Eigen::Matrix3d::Zero();
  fit.common.covariance(0, 0) = fit.exponent_standard_error * fit.exponent_standard_error;
  fit.common.covariance.bottomRightCorner<2, 2>() = fit.lognormal_covariance;
  fit.common.log_likelihood = std::max(fit.power_law_log_likelihood, fit.lognormal_log_likelihood);
  fit.common.goodness_of_fit = {{"ks-power-law", fit.power_law_ks, std::nullopt, std::nullopt},
                                {"ks-lognormal", fit.lognormal_ks, std::nullopt, std::nullopt},
                                {"vuong", fit.vuong_statistic, std::nullopt, fit.vuong_p_value}};
  fit.common.validity = {
      {"fragment_size", static_cast<double>(counts.begin()->first), static_cast<double>(counts.rbegin()->first)}};
  return fit;
}

std::vector<FragmentSizeFit> fit_fragment_distributions(const CaseOutcomeTable& table) {
  const auto by_point = cases_by_point(table);
  std::vector<FragmentSizeFit> fits;
  for (std::size_t g = 0; g < by_point.size(); ++g) {
    std::vector<std::int64_t> sizes;
    std::int64_t largest = 0;
    const auto determined = determined_cases(by_point[g]);
    for (const CaseOutcome* c : determined) {
      sizes.insert(sizes.end(), c->reentrained_sizes.begin(), c->reentrained_sizes.end());
      largest = std::max(largest, c->primaries);
    }
    if (sizes.empty()) continue;
    FragmentSizeFit fit = fit_fragment_sizes(sizes, largest);
    fit.common.name = "fragments.p" + std::to_string(g + 1);
    fit.common.group = table.grid_points[g];
    fit.common.cases = determined.size();
    fit.common.groups = 1;
    fit.common.small_strain_cases = small_strain_count(determined);
    fits.push_back(std::move(fit));
  }
  return fits;
}

}  // namespace aerobreak
