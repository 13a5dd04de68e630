#include "engine/dem/impact_placement.hpp"

#include <algorithm>
#include <limits>

namespace aerobreak {

Particles particles_from_cluster(const Cluster& cluster, double density, std::uint16_t material) {
  Particles p;
  p.reserve(cluster.size());
  for (std::size_t i = 0; i < cluster.size(); ++i) p.add(cluster.position[i], cluster.radius[i], density, material);
  return p;
}

Cluster cluster_from_particles(const Particles& particles) { return {particles.position, particles.radius}; }

Particles place_for_impact(const Particles& cluster, const Rotation& orientation, const Wall& wall, double gap,
                           const Vec3& velocity) {
  Particles p = cluster;
  const Vec3 centre = p.centre_of_mass();
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.position[i] = orientation.apply(p.position[i] - centre);
    lowest = std::min(lowest, dot(p.position[i], wall.normal) - p.radius[i]);
  }
  const Vec3 shift = wall.point + (gap - lowest) * wall.normal;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.position[i] += shift;
    p.velocity[i] = velocity;
    p.angular_velocity[i] = {};
  }
  p.clear_forces();
  return p;
}

}  // namespace aerobreak
