#pragma once
#include <cstddef>
#include <optional>
#include <span>

namespace aerobreak {

// z of the two-sided 95 % normal interval.
inline constexpr double kZ95 = 1.959963984540054;

// A binomial proportion with its Wilson score interval (E. B. Wilson, J. Am. Stat. Assoc. 22
// (1927) 209): unlike the normal approximation it stays inside [0, 1] and is usable for the few
// replicates per grid point that impact sweeps afford, and for k = 0 or k = n.
struct ProportionEstimate {
  double probability = 0.0;  // k / n
  double lower = 0.0;
  double upper = 0.0;
};

// z = 1.959964 gives the 95 % interval. nullopt when n = 0 (no information).
std::optional<ProportionEstimate> wilson_interval(std::size_t successes, std::size_t trials, double z = kZ95);

// A sample mean with its standard error s / sqrt(n) (s with n - 1 degrees of freedom; null for
// n = 1) and the 95 % normal interval mean +- 1.96 SE.
struct MeanWithError {
  std::size_t n = 0;
  double mean = 0.0;
  std::optional<double> standard_error;
};
std::optional<MeanWithError> mean_estimate(std::span<const double> values);

// A ratio of sums sum(a_i) / sum(b_i) over independent units i (cases), with the linearised
// (delta-method) standard error of the ratio estimator (Cochran, Sampling Techniques, 3rd ed.,
// eq 6.13): SE^2 = sum (a_i - R b_i)^2 / (n (n - 1) mean(b)^2). For a mean fragment size the units
// are the cases, whose fragments are not independent of each other. nullopt when sum(b) = 0.
std::optional<MeanWithError> ratio_estimate(std::span<const double> numerators, std::span<const double> denominators);

}  // namespace aerobreak
