#include "orchestrator/fitting/proportion.hpp"

#include <algorithm>
#include <cmath>
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

}  // namespace aerobreak
