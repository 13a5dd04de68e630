#pragma once
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "engine/cluster/random_stream.hpp"
#include "engine/cluster/rotation.hpp"
#include "engine/core/vec3.hpp"

namespace aerobreak {

// The Langevin bath of one primary (dem/body_forces.hpp): drag zeta on its velocity, zeta_r =
// zeta d^2 / 3 on its spin, noise from kT by the fluctuation-dissipation theorem.
struct PrimaryBath {
  double radius = 0.5;
  double mass = 1.0;
  double inertia = 0.1;      // 2/5 m R^2
  double drag = 0.0;         // zeta
  double spin_drag = 0.0;    // zeta d^2 / 3
  double temperature = 0.0;  // kT
};

// A cluster of bonded primaries advanced as one rigid body in that bath while no other cluster is
// near. With primary i at r_i from the centre of mass, velocity V + Omega x r_i and spin Omega,
// the free-draining bath (every primary feels its own drag and noise; Isella & Drossinos 2010)
// sums to
//   force  -n zeta V + sum_i f_i,                 <F F^T> = 2 n zeta kT / dt   (translation),
//   torque -Z Omega + sum_i (r_i x f_i + t_i),    Z = zeta S + n zeta_r 1     (rotation),
// with S = sum_i (|r_i|^2 1 - r_i r_i^T). The cross terms vanish, sum_i r_i x (-zeta V) and the
// force-torque noise covariance being proportional to sum_i r_i = 0 for equal drags about the
// centre of mass, so translation and rotation are independent Langevin processes. The inertia
// tensor I = m S + n (2/5) m R^2 1 has the same eigenvectors as Z (both a S + b 1): along each
// principal axis of S the spin is a scalar Langevin process with inertia I_k and drag Z_k, and
// the noise covariance 2 kT Z keeps the Maxwell distribution kT / I_k. Each step advances the
// three translation components (mass n m, drag n zeta) and the three principal spins with the
// exact Ornstein-Uhlenbeck update (ornstein_uhlenbeck.hpp), so the centre of mass diffuses with
// D = kT / (n zeta) and the rotation with D_k = kT / Z_k, the engine's per-primary Langevin
// dynamics of a rigid cluster, at any step. Left out: the gyroscopic term (I_k+1 - I_k+2)
// Omega_k+1 Omega_k+2 of Euler's equations, which exchanges spin between axes without changing its
// energy or Maxwell distribution; the step keeps the rotation per step small (step_for_reach).
struct RigidCluster {
  std::vector<std::size_t> members;                       // particle indices
  std::vector<Vec3> body;                                 // member centres about the centre of mass, principal frame
  Vec3 centre;                                            // centre of mass, never wrapped
  Vec3 velocity;                                          // of the centre of mass
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  // unit quaternion (w, x, y, z), body to space
  Vec3 spin;                                              // angular velocity in the principal frame
  double mass = 0.0;                                      // n m
  double drag = 0.0;                                      // n zeta
  Vec3 inertia;                                           // principal moments I_k
  Vec3 rotational_drag;                                   // principal drags Z_k
  double reach = 0.0;                                     // farthest surface point from the centre of mass
};

// The rigid body of `members` at `position` (one piece: unwrapped or reassembled), moving with the
// primaries' mean velocity and the angular velocity of their angular momentum about the centre.
RigidCluster rigid_cluster(std::vector<std::size_t> members, std::span<const Vec3> position,
                           std::span<const Vec3> velocity, std::span<const Vec3> angular_velocity,
                           const PrimaryBath& bath);

// Advances by dt, drawing twelve standard normals from `random`. Returns a bound on how far any
// member moved: the centre's displacement plus reach times the rotation angle.
double propagate(RigidCluster& cluster, double dt, double temperature, RandomStream& random);

// Body to space.
Rotation orientation_matrix(const RigidCluster& cluster);
// Member centres (never wrapped) and velocities V + Omega x r_k, in the order of `members`.
std::vector<Vec3> member_positions(const RigidCluster& cluster);
std::vector<Vec3> member_velocities(const RigidCluster& cluster);
Vec3 angular_velocity(const RigidCluster& cluster);  // space frame

// The largest step whose thermal mean square displacement of every member, translation plus
// rotation, stays below allowed^2, and whose mean square rotation angle stays below
// max_angle^2 (clusters of two or more). The bound per member at distance <= reach from the
// centre: MSD(dt) <= min(a1 dt, a2 dt^2), a1 = 6 kT / (n zeta) + 2 kT reach^2 sum_k 1 / Z_k
// (diffusive) and a2 = 3 kT / (n m) + kT reach^2 sum_k 1 / I_k (ballistic), since the
// Ornstein-Uhlenbeck displacement lies below both limits.
double step_for_reach(const RigidCluster& cluster, double temperature, double allowed, double max_angle);

}  // namespace aerobreak
