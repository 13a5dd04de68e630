#pragma once
#include <cstddef>
#include <optional>

// Means of per-grid-point samples with their Student intervals, for the dashboard's grid and the
// lookup tables; the Wilson interval of the outcome probabilities and kZ95 are in proportion.hpp.
#include "orchestrator/fitting/proportion.hpp"

namespace aerobreak {

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
