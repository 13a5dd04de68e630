#pragma once
#include <cstddef>
#include <cstdint>

#include "engine/core/particles.hpp"

namespace aerobreak {

// Langevin (Brownian) dynamics for cluster growth: drag -zeta v and a random force of variance
// 2 zeta kT / dt per component (fluctuation-dissipation theorem), plus the rotational pair
// -zeta_r w with zeta_r = zeta d^2 / 3 (Stokes: 3 pi mu d and pi mu d^3). zeta = c d with
// c = drag_per_diameter (Stokes: 3 pi mu / C_c). Seeded and counter-based: the same seed, step
// and particle always draw the same numbers.
struct Langevin {
  double temperature = 0.0;        // kT in energy units
  double drag_per_diameter = 0.0;  // c; 0 switches Langevin dynamics off
  std::uint64_t seed = 0;

  bool enabled() const { return drag_per_diameter > 0.0; }
};

struct BodyForces {
  Vec3 gravity;  // acceleration
  Langevin langevin;
};

// Adds gravity and Langevin forces to the particles begin .. end-1, and to `work` the work the
// Langevin forces did on them over this step (evaluated with the half-step velocities of
// velocity Verlet), in particle order: ranges add up as one pass over all particles would.
void add_body_forces(Particles& particles, const BodyForces& body, std::int64_t step, double dt, std::size_t begin,
                     std::size_t end, double& work);

// Potential energy in the gravity field, -sum m g.x.
double gravitational_energy(const Particles& particles, const Vec3& gravity);

}  // namespace aerobreak
