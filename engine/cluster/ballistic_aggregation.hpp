#pragma once
#include <cstddef>
#include <cstdint>

#include "engine/cluster/cluster.hpp"

namespace aerobreak {

// Parameters of ballistic cluster-cluster aggregation (BCCA). Primary diameters are lognormal with
// geometric mean `geometric_mean_diameter` and geometric standard deviation
// `geometric_standard_deviation` (ln d ~ Normal(ln d_g, ln sigma_g)); sigma_g = 1 (the default)
// is monodisperse.
struct BallisticAggregationParameters {
  std::size_t primary_count = 1;
  double geometric_mean_diameter = 1.0;
  double geometric_standard_deviation = 1.0;
};

// Hierarchical ballistic cluster-cluster aggregation with linear trajectories (Jullien 1984,
// J. Phys. A 17 L771). Clusters of (nearly) equal size are paired; the second of each pair gets a
// uniformly random orientation and is fired along a random straight line at the first; it sticks
// where two primaries first touch (centre distance exactly r_i + r_j); a miss draws a new line
// (direction and impact parameter), keeping the orientation.
//
// Any primary_count >= 1 works: a cluster of n primaries is built from clusters of ceil(n/2) and
// floor(n/2) primaries, so partners never differ by more than one primary. For n = 2^k this is
// Jullien's level-by-level pairing tree; otherwise the odd cluster of a level is in effect merged
// one level early rather than carried (carrying would pair very unequal clusters at the end).
//
// The result is centred on its centre of mass (mass ~ r^3), its primaries listed along their
// neighbours (ordered_along_neighbours). The same parameters and seed give
// bit-identical output on the same build. Throws std::invalid_argument naming the offending
// parameter for primary_count < 1, a non-positive or non-finite diameter, or sigma_g < 1.
Cluster ballistic_cluster_cluster_aggregation(const BallisticAggregationParameters& parameters, std::uint64_t seed);

}  // namespace aerobreak
