#include "engine/cluster/ballistic_aggregation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/cluster/ballistic_collision.hpp"
#include "engine/cluster/neighbour_order.hpp"
#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/random_stream.hpp"

namespace aerobreak {
namespace {

// A miss costs O(N) and the hit probability of a random line through the bounding disc is of order
// the projected area fraction, so this bound is only reached if something is badly wrong.
constexpr int max_trajectories_per_pair = 1'000'000;

void validate(const BallisticAggregationParameters& p) {
  if (p.primary_count < 1) {
    throw std::invalid_argument("BCCA: primary_count must be >= 1");
  }
  if (!(p.geometric_mean_diameter > 0.0) || !std::isfinite(p.geometric_mean_diameter)) {
    throw std::invalid_argument("BCCA: geometric_mean_diameter must be positive and finite, got " +
                                std::to_string(p.geometric_mean_diameter));
  }
  if (!(p.geometric_standard_deviation >= 1.0) || !std::isfinite(p.geometric_standard_deviation)) {
    throw std::invalid_argument("BCCA: geometric_standard_deviation must be >= 1 and finite, got " +
                                std::to_string(p.geometric_standard_deviation));
  }
}

void recentre(Cluster& c) {
  const Vec3 com = centre_of_mass(c);
  for (Vec3& x : c.position) x -= com;
}

// Radius of the smallest sphere about the origin (the centre of mass) enclosing every primary.
double bounding_radius(const Cluster& c) {
  double r = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) r = std::max(r, norm(c.position[i]) + c.radius[i]);
  return r;
}

// One collision of the hierarchy: both clusters are centred on their centres of mass. The
// projectile is rotated uniformly at random, then launched along a random direction u with a
// random impact parameter b uniform over the disc of radius R_t + R_p normal to u (every line that
// can touch the target's bounding sphere), from R_t + R_p behind the target's centre so the two
// bounding spheres start apart. It sticks at the first touch; a miss draws a new line.
Cluster collide(Cluster target, Cluster projectile, RandomStream& random) {
  const Rotation orientation = random.rotation();
  for (Vec3& y : projectile.position) y = orientation.apply(y);
  const double reach = bounding_radius(target) + bounding_radius(projectile);

  for (int attempt = 0; attempt < max_trajectories_per_pair; ++attempt) {
    const FlightFrame frame = flight_frame(random.unit_vector());
    const double b = reach * std::sqrt(random.uniform());
    const double phi = 2.0 * std::numbers::pi * random.uniform();
    const Vec3 start = b * (std::cos(phi) * frame.e1 + std::sin(phi) * frame.e2) - reach * frame.u;

    Cluster launched = projectile;
    for (Vec3& y : launched.position) y += start;
    const std::optional<double> travel = first_contact_travel(target, launched, frame.u);
    if (!travel) continue;

    const Vec3 shift = *travel * frame.u;
    for (std::size_t j = 0; j < launched.size(); ++j) {
      target.position.push_back(launched.position[j] + shift);
      target.radius.push_back(launched.radius[j]);
    }
    recentre(target);
    return target;
  }
  throw std::runtime_error("BCCA: no trajectory hit the target cluster");
}

// Builds the cluster of primaries [first, first + count) of `radii`: the aggregate of the clusters
// of the first ceil(count/2) and the last floor(count/2) of them (Jullien's hierarchical pairing).
Cluster aggregate(const std::vector<double>& radii, std::size_t first, std::size_t count, RandomStream& random) {
  if (count == 1) return Cluster{{Vec3{}}, {radii[first]}};
  const std::size_t larger = count - count / 2;
  Cluster target = aggregate(radii, first, larger, random);
  Cluster projectile = aggregate(radii, first + larger, count / 2, random);
  return collide(std::move(target), std::move(projectile), random);
}

}  // namespace

Cluster ballistic_cluster_cluster_aggregation(const BallisticAggregationParameters& parameters, std::uint64_t seed) {
  validate(parameters);
  RandomStream random(seed);
  const std::vector<double> radii = random.lognormal_radii(parameters.primary_count, parameters.geometric_mean_diameter,
                                                           parameters.geometric_standard_deviation);
  return ordered_along_neighbours(aggregate(radii, 0, radii.size(), random));
}

}  // namespace aerobreak
