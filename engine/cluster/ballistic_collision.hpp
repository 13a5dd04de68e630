#pragma once
#include <optional>

#include "engine/cluster/cluster.hpp"
#include "engine/core/vec3.hpp"

namespace aerobreak {

// Orthonormal frame of a straight flight: e1 and e2 span the plane normal to the direction u.
struct FlightFrame {
  Vec3 e1, e2, u;
};
FlightFrame flight_frame(const Vec3& unit_direction);

// The first touch between a fixed target cluster and a projectile cluster that translates rigidly
// along a straight line (the linear trajectories of ballistic aggregation, Jullien 1984).
//
// Returns the distance the projectile must travel along `direction` (a unit vector) from its
// current placement until a projectile primary j first touches a target primary i, i.e. until
// |x_i - (y_j + s u)| = r_i + r_j; std::nullopt when the line misses. Precondition: the projectile
// starts clear of and behind the target along `direction` (both bounding spheres disjoint and the
// projectile's behind the target's), so every pair's first root s is non-negative.
//
// Cost: O(N_target + N_projectile) per call. Two primaries can touch only if the perpendicular
// distance between the projectile primary's path and the target primary is at most r_i + r_j, so
// the target is projected onto the plane normal to `direction` and binned in a 2-D cell grid of
// cell size >= max r_i + max r_j; each projectile primary then marches down its own column of
// cells (its 3x3 neighbourhood) and meets only the target primaries in that column.
std::optional<double> first_contact_travel(const Cluster& target, const Cluster& projectile, const Vec3& direction);

}  // namespace aerobreak
