#pragma once
#include <cstddef>
#include <optional>

namespace aerobreak {

// A binomial proportion with its Wilson score interval (E. B. Wilson, J. Am. Stat. Assoc. 22
// (1927) 209): unlike the normal approximation it stays inside [0, 1] and is usable for the few
// replicates per grid point that impact sweeps afford, and for k = 0 or k = n.
struct ProportionEstimate {
  double probability = 0.0;  // k / n
  double lower = 0.0;
  double upper = 0.0;
};

// z = 1.959964 gives the 95 % interval. nullopt when n = 0 (no information).
std::optional<ProportionEstimate> wilson_interval(std::size_t successes, std::size_t trials, double z = 1.959963984540054);

// The 0.975 quantile of Student's t distribution with `degrees_of_freedom` (>= 1): exact for 1 and
// 2, the Cornish-Fisher expansion of Abramowitz & Stegun 26.7.5 (four terms) from 3 on, within
// 0.12 % at 3 and 0.002 % from 10 on.
double student_t_975(std::size_t degrees_of_freedom);

// A sample mean with its standard deviation and its 95 % interval, mean -/+ t s / sqrt(n) (Student,
// Biometrika 6 (1908) 1); the standard deviation and the interval need n >= 2.
struct MeanEstimate {
  std::size_t count = 0;
  double mean = 0.0;
  std::optional<double> standard_deviation;
  std::optional<double> lower;
  std::optional<double> upper;
};

// From the count, sum and sum of squares of the sample; nullopt when it is empty.
std::optional<MeanEstimate> mean_interval(std::size_t count, double sum, double sum_of_squares);

}  // namespace aerobreak
