#pragma once
#include <cstddef>
#include <vector>

#include "engine/cluster/tunable_scaling_law.hpp"
#include "engine/core/vec3.hpp"

namespace aerobreak {

// An intermediate aggregate of the tunable generator: positions relative to its mass-weighted
// centre, with the mass (sum of r^3) and radius of gyration the aggregation steps need.
struct TunableAggregate {
  std::vector<Vec3> position;
  std::vector<double> radius;
  double mass = 0.0;
  double gyration_radius = 0.0;
  double log_radius_sum = 0.0;  // sum ln r_i, for the law's geometric mean radius

  std::size_t size() const { return position.size(); }
};

// Moves the primaries so that their centre of mass is the origin and measures mass and Rg under
// the convention.
TunableAggregate centred_aggregate(std::vector<Vec3> position, std::vector<double> radius,
                                   GyrationConvention convention);

}  // namespace aerobreak
