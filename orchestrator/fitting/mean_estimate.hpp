#pragma once
#include <cstddef>
#include <optional>
#include <span>

// The one definition of a mean over replicates with its error and its 95 % interval: the
// correlation documents' grid points, the dashboard's grid, the outcome table and the lookup tables
// all take theirs from here (docs/CORRELATIONS.md, "Per grid point"). The Wilson interval of the
// outcome probabilities and kZ95 are in proportion.hpp.
#include "orchestrator/fitting/proportion.hpp"

namespace aerobreak {

// The 0.975 quantile of Student's t distribution with `degrees_of_freedom` (>= 1): R's
// qt(0.975, 1:30) to the last digit up to 30, then the Cornish-Fisher expansion of Abramowitz &
// Stegun 26.7.5 (four terms), within 1.3e-8 of qt from 31 on.
double student_t_975(std::size_t degrees_of_freedom);

// A mean over n independent replicates (the cases of a grid point) with its sample standard
// deviation s (n - 1 degrees of freedom), its standard error SE = s / sqrt(n) and its 95 % interval
//   mean -/+ t(0.975, n - 1) SE                                  (Student, Biometrika 6 (1908) 1).
// Student's t rather than the normal 1.96: a grid point has few replicates (3 to 20), where the
// normal interval mean -/+ 1.96 SE is too narrow: for normal data it covers 81 % at n = 3, 88 % at n = 5
// (R: 2 * pt(1.959964, c(2, 4)) - 1).
// s, SE and the interval need n >= 2; with n = 1 they are null, never a guess.
struct MeanEstimate {
  std::size_t count = 0;
  double mean = 0.0;
  std::optional<double> standard_deviation;
  std::optional<double> standard_error;
  std::optional<double> lower;
  std::optional<double> upper;
};

// The rule above, from the count, the mean and the sample variance s^2 (ignored below 2): the one
// place where s, SE and the interval are computed.
MeanEstimate mean_with_interval(std::size_t count, double mean, double variance);

// From the values themselves, in two passes (the mean, then the squared deviations from it), which
// loses no digits to cancellation. The correlation documents' means (fitting/grid_aggregates.cpp).
// nullopt when there is none.
std::optional<MeanEstimate> mean_estimate(std::span<const double> values);

// From streamed moments: the count, the sum and the sum of squared deviations from the mean
// M2 = sum (x - mean)^2, which the store accumulates by Welford's update (B. P. Welford,
// Technometrics 4 (1962) 419) inside its one-pass SQL aggregation, as stable as two passes
// (store_statistics_functions.cpp). The dashboard's grid, the outcome table and the lookup tables.
// nullopt when the count is 0.
std::optional<MeanEstimate> streamed_mean_estimate(std::size_t count, double sum, double squared_deviations);

// A ratio of sums R = sum(a_i) / sum(b_i) over independent units i (cases), with the linearised
// (delta-method) standard error of the ratio estimator (Cochran, Sampling Techniques, 3rd ed.,
// eq 6.13): SE^2 = sum (a_i - R b_i)^2 / (n (n - 1) mean(b)^2). Its standard deviation is that of
// the linearised values (a_i - R b_i) / mean(b), so that SE = s / sqrt(n) and the interval is the
// same rule as a mean's, R -/+ t(0.975, n - 1) SE. For a mean fragment size the units are the
// cases, whose fragments are not independent of each other. nullopt when sum(b) = 0.
std::optional<MeanEstimate> ratio_estimate(std::span<const double> numerators, std::span<const double> denominators);

}  // namespace aerobreak
