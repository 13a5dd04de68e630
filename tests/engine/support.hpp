#pragma once
// Small builders shared by the engine tests.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/core/units.hpp"
#include "engine/dem/relaxation.hpp"
#include "engine/dem/simulation.hpp"

namespace aerobreak::testing {

// Unit-diameter, unit-mass sphere material in reduced units (k_n = 1, eq 7).
inline Material unit_material(double gamma_over_kn = 0.01, double poisson = 0.3) {
  return reduced_material(gamma_over_kn, poisson);
}

inline double unit_density() { return 6.0 / std::numbers::pi; }

// A random self-avoiding chain of touching unit spheres, branching off random earlier members.
inline Particles random_touching_cluster(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Particles p;
  p.add({0, 0, 0}, 0.5, unit_density());
  while (p.size() < n) {
    const std::size_t parent = std::uniform_int_distribution<std::size_t>(0, p.size() - 1)(rng);
    Vec3 dir{uniform(rng), uniform(rng), uniform(rng)};
    if (norm2(dir) < 1e-3 || norm2(dir) > 1.0) continue;
    dir = dir / norm(dir);
    const Vec3 at = p.position[parent] + dir;
    bool clear = true;
    for (std::size_t k = 0; k < p.size() && clear; ++k) clear = k == parent || norm(p.position[k] - at) >= 1.0;
    if (clear) p.add(at, 0.5, unit_density());
  }
  return p;
}

// The cluster above, relaxed to JKR equilibrium (contacts at their equilibrium overlap, at rest).
inline Particles relaxed_cluster(std::size_t n, std::uint64_t seed, double gamma_over_kn = 0.01) {
  return relax_cluster(random_touching_cluster(n, seed), {unit_material(gamma_over_kn)}, ContactModelSpec{}).particles;
}

// Every law on: JKR, visco-elastic damping, Mindlin friction, rolling and twisting resistance.
inline ContactModelSpec full_model() {
  ContactModelSpec spec;
  spec.damping = DampingLaw::viscoelastic;
  spec.dissipative_time = 0.5;
  spec.friction = 0.3;
  spec.rolling = true;
  spec.critical_rolling = 0.01;
  spec.twisting = true;
  return spec;
}

// Settings that bond a relaxed cluster's contacts from the first step.
inline SimulationSettings bonded() {
  SimulationSettings settings;
  settings.initial_bond_gap = 1e-6;
  return settings;
}

// Lifts a cluster so that its lowest centre is `height` above the plane z = 0 (a floor wall's
// surface) and sends every particle off with `velocity`.
inline void launch_above_floor(Particles& p, double height, const Vec3& velocity) {
  double lowest = 1e300;
  for (const auto& x : p.position) lowest = std::min(lowest, x.z);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.position[i].z += height - lowest;
    p.velocity[i] = velocity;
  }
}

// An adhesive floor (the plane z = 0, normal +z) and a wall without adhesion at x = -3 facing +x:
// a cluster launched above the floor hits one, then perhaps the other.
inline std::vector<Wall> floor_and_side_walls() {
  Wall floor;
  floor.adhesive = true;
  Wall side{{-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
  side.adhesive = false;
  return {floor, side};
}

// Gravity and a Langevin bath, weak enough to leave an impact's contact dynamics in charge.
inline BodyForces gravity_and_bath() {
  BodyForces body;
  body.gravity = {0.0, 0.0, -1e-3};
  body.langevin = {1e-6, 0.05, 77};
  return body;
}

inline Vec3 linear_momentum(const Particles& p) {
  Vec3 total;
  for (std::size_t i = 0; i < p.size(); ++i) total += p.mass[i] * p.velocity[i];
  return total;
}

inline Vec3 angular_momentum(const Particles& p) {
  Vec3 total;
  for (std::size_t i = 0; i < p.size(); ++i)
    total += p.mass[i] * cross(p.position[i], p.velocity[i]) + p.inertia[i] * p.angular_velocity[i];
  return total;
}

}  // namespace aerobreak::testing
