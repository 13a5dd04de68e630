#pragma once
#include <cstddef>
#include <vector>

#include "engine/cluster/random_stream.hpp"
#include "engine/core/vec3.hpp"
#include "engine/neighbor/periodic_box.hpp"

namespace aerobreak {

// Edge of the cube that holds `count` spheres of diameter d at volume fraction phi:
// L = (count pi d^3 / (6 phi))^(1/3).
double cube_edge_for_volume_fraction(std::size_t count, double diameter, double volume_fraction);

// `count` centres drawn uniformly in the periodic box, each kept only if its nearest-image
// distance to every centre kept before is at least `min_distance` (random sequential addition;
// Widom 1966): no two spheres of diameter < min_distance touch. Throws std::runtime_error after
// 1000 count failed draws in a row (the box is too full).
std::vector<Vec3> random_sequential_positions(std::size_t count, const PeriodicBox& box, double min_distance,
                                              RandomStream& random);

}  // namespace aerobreak
