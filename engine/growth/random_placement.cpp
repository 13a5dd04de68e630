#include "engine/growth/random_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace aerobreak {

double cube_edge_for_volume_fraction(std::size_t count, double diameter, double volume_fraction) {
  if (!(volume_fraction > 0.0) || !(volume_fraction < 1.0))
    throw std::invalid_argument("volume fraction must lie in (0, 1)");
  const double solid = static_cast<double>(count) * std::numbers::pi * diameter * diameter * diameter / 6.0;
  return std::cbrt(solid / volume_fraction);
}

std::vector<Vec3> random_sequential_positions(std::size_t count, const PeriodicBox& box, double min_distance,
                                              RandomStream& random) {
  box.validate();
  std::vector<Vec3> kept;
  kept.reserve(count);
  const double limit2 = min_distance * min_distance;
  const std::size_t patience = 1000 * std::max<std::size_t>(count, 1);
  std::size_t failures = 0;
  while (kept.size() < count) {
    const Vec3 x{random.uniform() * box.length.x, random.uniform() * box.length.y, random.uniform() * box.length.z};
    bool clear = true;
    for (std::size_t k = 0; k < kept.size() && clear; ++k) clear = norm2(box.minimum_image(kept[k] - x)) >= limit2;
    if (clear) {
      kept.push_back(x);
      failures = 0;
    } else if (++failures > patience) {
      throw std::runtime_error("random placement: no room for sphere " + std::to_string(kept.size() + 1) + " of " +
                               std::to_string(count) + " in the box");
    }
  }
  return kept;
}

}  // namespace aerobreak
