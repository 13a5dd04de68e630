#pragma once
#include <cstdint>

#include "engine/cluster/cluster.hpp"
#include "engine/cluster/rotation.hpp"
#include "engine/core/particles.hpp"
#include "engine/dem/wall.hpp"

namespace aerobreak {

// Spheres of one material and density at the cluster's positions and radii, at rest.
Particles particles_from_cluster(const Cluster& cluster, double density, std::uint16_t material = 0);
Cluster cluster_from_particles(const Particles& particles);

// Sets a cluster up for an impact (docs/IMPACT.md section 3, docs/MODEL.md 11.2): turned by `orientation`
// about its centre of mass, moved so that its lowest surface is `gap` above the wall (no long
// free flight) with the centre of mass over the wall's point, and every primary given
// `velocity`; spins are zero.
Particles place_for_impact(const Particles& cluster, const Rotation& orientation, const Wall& wall, double gap,
                           const Vec3& velocity);

}  // namespace aerobreak
