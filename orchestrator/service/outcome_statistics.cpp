#include "orchestrator/service/outcome_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace aerobreak {

std::optional<ProportionEstimate> wilson_interval(std::size_t successes, std::size_t trials, double z) {
  if (successes > trials) throw std::invalid_argument("more successes than trials");
  if (trials == 0) return std::nullopt;
  const double n = static_cast<double>(trials);
  const double p = static_cast<double>(successes) / n;
  const double z2 = z * z;
  // Centre (p + z^2/2n) / (1 + z^2/n), half-width z sqrt(p(1-p)/n + z^2/4n^2) / (1 + z^2/n).
  const double denominator = 1.0 + z2 / n;
  const double centre = (p + z2 / (2.0 * n)) / denominator;
  const double half_width = z * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n)) / denominator;
  // For k = 0 the lower bound is exactly 0 (and for k = n the upper bound exactly 1): centre and
  // half-width are then equal in exact arithmetic, and their difference in doubles is round-off
  // (5.55e-17 for k = 0, n = 20).
  const double lower = successes == 0 ? 0.0 : std::max(0.0, centre - half_width);
  const double upper = successes == trials ? 1.0 : std::min(1.0, centre + half_width);
  return ProportionEstimate{p, lower, upper};
}

double student_t_975(std::size_t degrees_of_freedom) {
  if (degrees_of_freedom == 0) throw std::invalid_argument("Student's t needs at least one degree of freedom");
  constexpr double p = 0.975;
  if (degrees_of_freedom == 1) return std::tan(std::numbers::pi * (p - 0.5));
  if (degrees_of_freedom == 2) return (2.0 * p - 1.0) * std::sqrt(2.0 / (4.0 * p * (1.0 - p)));
  // A&S 26.7.5: t = z + g1/nu + g2/nu^2 + g3/nu^3 + g4/nu^4, z the normal quantile.
  const double z = 1.959963984540054;
  const double z2 = z * z;
  const double g1 = (z2 + 1.0) * z / 4.0;
  const double g2 = ((5.0 * z2 + 16.0) * z2 + 3.0) * z / 96.0;
  const double g3 = (((3.0 * z2 + 19.0) * z2 + 17.0) * z2 - 15.0) * z / 384.0;
  const double g4 = ((((79.0 * z2 + 776.0) * z2 + 1482.0) * z2 - 1920.0) * z2 - 945.0) * z / 92160.0;
  const double nu = static_cast<double>(degrees_of_freedom);
  return z + (g1 + (g2 + (g3 + g4 / nu) / nu) / nu) / nu;
}

std::optional<MeanEstimate> mean_interval(std::size_t count, double sum, double sum_of_squares) {
  if (count == 0) return std::nullopt;
  const double n = static_cast<double>(count);
  MeanEstimate estimate{count, sum / n, std::nullopt, std::nullopt, std::nullopt};
  if (count < 2) return estimate;
  const double variance = std::max(0.0, (sum_of_squares - sum * sum / n) / (n - 1.0));
  const double half_width = student_t_975(count - 1) * std::sqrt(variance / n);
  estimate.standard_deviation = std::sqrt(variance);
  estimate.lower = estimate.mean - half_width;
  estimate.upper = estimate.mean + half_width;
  return estimate;
}

}  // namespace aerobreak
