#pragma once
#include <cstddef>
#include <optional>

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

}  // namespace aerobreak
