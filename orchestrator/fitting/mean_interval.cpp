#include "orchestrator/fitting/mean_interval.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace aerobreak {

double student_t_975(std::size_t degrees_of_freedom) {
  if (degrees_of_freedom == 0) throw std::invalid_argument("Student's t needs at least one degree of freedom");
  constexpr double p = 0.975;
  if (degrees_of_freedom == 1) return std::tan(std::numbers::pi * (p - 0.5));
  if (degrees_of_freedom == 2) return (2.0 * p - 1.0) * std::sqrt(2.0 / (4.0 * p * (1.0 - p)));
  // A&S 26.7.5: t = z + g1/nu + g2/nu^2 + g3/nu^3 + g4/nu^4, z the normal quantile.
  const double z = kZ95;
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
