#include "engine/cluster/random_stream.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace aerobreak {

double RandomStream::uniform() {
  constexpr double two_to_minus_53 = 0x1.0p-53;
  return static_cast<double>(engine_() >> 11) * two_to_minus_53;
}

double RandomStream::standard_normal() {
  const double u1 = 1.0 - uniform();  // (0, 1]: keeps the logarithm finite
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

Vec3 RandomStream::unit_vector() {
  const double z = 2.0 * uniform() - 1.0;
  const double azimuth = 2.0 * std::numbers::pi * uniform();
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(azimuth), s * std::sin(azimuth), z};
}

Rotation RandomStream::rotation() {
  const double u1 = uniform();
  const double theta1 = 2.0 * std::numbers::pi * uniform();
  const double theta2 = 2.0 * std::numbers::pi * uniform();
  const double s1 = std::sqrt(1.0 - u1);
  const double s2 = std::sqrt(u1);
  return Rotation::from_unit_quaternion(s2 * std::cos(theta2), s1 * std::sin(theta1), s1 * std::cos(theta1),
                                        s2 * std::sin(theta2));
}

std::vector<double> RandomStream::lognormal_radii(std::size_t n, double geometric_mean_diameter,
                                                  double geometric_standard_deviation) {
  std::vector<double> radii(n, 0.5 * geometric_mean_diameter);
  if (geometric_standard_deviation == 1.0) return radii;
  const double log_sigma = std::log(geometric_standard_deviation);
  for (double& r : radii) r *= std::exp(log_sigma * standard_normal());
  return radii;
}

}  // namespace aerobreak
