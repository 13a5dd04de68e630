#include "orchestrator/search/optimal_design.hpp"

#include <cmath>
#include <limits>
#include <map>

namespace aerobreak {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Standard normal deviates by Box-Muller from splitmix64: the same numbers on every platform.
class NormalDraws {
 public:
  explicit NormalDraws(std::uint64_t seed) : state_(seed) {}
  double next() {
    const double u1 = (static_cast<double>(splitmix64(state_) >> 11) + 0.5) * 0x1.0p-53;
    const double u2 = (static_cast<double>(splitmix64(state_) >> 11) + 0.5) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
  }

 private:
  std::uint64_t state_;
};

double logistic_of(double x) { return 1.0 / (1.0 + std::exp(-x)); }

// The information of (b0, b1) that one case at dose x carries under the parameters b.
Eigen::Matrix2d case_information(const Eigen::Vector2d& b, double x) {
  const double p = logistic_of(b[0] + b[1] * x);
  const double w = p * (1.0 - p);
  Eigen::Matrix2d m;
  m << w, w * x, w * x, w * x * x;
  return m;
}

// One parameter draw of one response: the information of the results so far under it.
struct Draw {
  Eigen::Vector2d b;
  Eigen::Matrix2d information;
};

std::vector<Draw> draws_of(const ResponseFit& fit, int count, NormalDraws& normal) {
  const Eigen::Vector2d mean = fit.fit->coefficients;
  const Eigen::LLT<Eigen::Matrix2d> cholesky(fit.fit->covariance);
  std::vector<Draw> out;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector2d z(normal.next(), normal.next());
    Eigen::Vector2d b =
        cholesky.info() == Eigen::Success && k > 0 ? Eigen::Vector2d(mean + cholesky.matrixL() * z) : mean;
    // A draw whose slope has the other sign describes another experiment: the estimate stands in.
    if (b[1] * mean[1] <= 0.0) b = mean;
    Eigen::Matrix2d m = 1e-9 * Eigen::Matrix2d::Identity();
    for (Eigen::Index i = 0; i < fit.data.trials.size(); ++i)
      m += fit.data.trials[i] * case_information(b, fit.data.design(i, 1));
    out.push_back({b, m});
  }
  return out;
}

// g' M^-1 g for the crossing of `level` under b.
double crossing_variance(const Eigen::Vector2d& b, const Eigen::Matrix2d& m, double level) {
  const double theta = (std::log(level / (1.0 - level)) - b[0]) / b[1];
  const double g0 = -1.0 / b[1], g1 = -theta / b[1];
  const double det = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  return (g0 * g0 * m(1, 1) - 2.0 * g0 * g1 * m(0, 1) + g1 * g1 * m(0, 0)) / det;
}

using DrawsByFit = std::map<const ResponseFit*, std::vector<Draw>>;

// sum over targets of E[Var(theta_t) | one more case at x] / half_width_t^2. The case is
// determined with chance q and adds its information only then: the variance after it is
// q Var(M + I_x) + (1 - q) Var(M). q = 1 (no undetermined result near x) is the plain criterion.
double crossings_criterion(const std::vector<DesignTarget>& targets, const DrawsByFit& by_fit, double x, double q) {
  double value = 0.0;
  for (const auto& target : targets) {
    const auto& draws = by_fit.at(target.fit);
    double sum = 0.0;
    for (const auto& draw : draws) {
      const double after = crossing_variance(draw.b, draw.information + case_information(draw.b, x), target.level);
      sum += q < 1.0 ? q * after + (1.0 - q) * crossing_variance(draw.b, draw.information, target.level) : after;
    }
    value += sum / static_cast<double>(draws.size()) / (target.half_width * target.half_width);
  }
  return value;
}

// -sum over fits of E[log det M | one more case at x], the case determined with chance q:
// q log det(M + I_x) + (1 - q) log det M.
double slope_criterion(const DrawsByFit& by_fit, double x, double q) {
  double value = 0.0;
  for (const auto& [fit, draws] : by_fit)
    for (const auto& draw : draws) {
      const double after = std::log((draw.information + case_information(draw.b, x)).determinant());
      value -= q < 1.0 ? q * after + (1.0 - q) * std::log(draw.information.determinant()) : after;
    }
  return value;
}

}  // namespace

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double expected_crossing_variance(const DesignTarget& target, std::uint64_t seed, int draws) {
  NormalDraws normal(seed);
  double sum = 0.0;
  for (const auto& draw : draws_of(*target.fit, draws, normal))
    sum += crossing_variance(draw.b, draw.information, target.level);
  return sum / static_cast<double>(draws);
}

std::vector<std::size_t> optimal_doses(const std::vector<DesignTarget>& targets, const std::vector<double>& candidates,
                                       const std::vector<double>& determined, std::size_t count, std::uint64_t seed,
                                       int draws) {
  NormalDraws normal(seed);
  // Draws per fit (targets of the same response share them).
  DrawsByFit by_fit;
  for (const auto& target : targets)
    if (!by_fit.count(target.fit)) by_fit.emplace(target.fit, draws_of(*target.fit, draws, normal));

  std::vector<std::size_t> picked;
  for (std::size_t pick = 0; pick < count; ++pick) {
    std::size_t best = 0;
    double best_value = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const double value = pick % 2 == 0 ? crossings_criterion(targets, by_fit, candidates[c], determined[c])
                                         : slope_criterion(by_fit, candidates[c], determined[c]);
      if (value < best_value) best_value = value, best = c;
    }
    picked.push_back(best);
    // The later picks of the round see the expected information of this one, q I_x (exactly I_x
    // at q = 1): its outcome is not known before the round ends.
    for (auto& [fit, fit_draws] : by_fit)
      for (auto& draw : fit_draws) draw.information += determined[best] * case_information(draw.b, candidates[best]);
  }
  return picked;
}

}  // namespace aerobreak
