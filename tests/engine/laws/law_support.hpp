#pragma once
// Builders shared by the contact-law tests: reduced-unit spheres (report section 3.1, eq 7:
// d = 1, m = 1, k_n = 1), hand-built contact constants, and a head-on impact on a wall.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "engine/contact/contact_constants.hpp"
#include "engine/core/material.hpp"
#include "engine/core/units.hpp"
#include "engine/dem/simulation.hpp"

namespace aerobreak::laws {

inline constexpr double unit_radius = 0.5;
inline constexpr double unit_density = 6.0 / std::numbers::pi;  // m = 1 for d = 1

inline double sphere_mass(double radius) {
  return unit_density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
}

// Constants of a contact between two spheres (radius_j > 0) or a sphere and a wall (radius_j = 0),
// completed by the given normal law.
template <class Normal>
ContactConstants contact_constants(const Normal& law, const Material& mi, const Material& mj,
                                   double radius_i = unit_radius, double radius_j = unit_radius) {
  const PairMaterial pair = combine(mi, mj);
  ContactConstants c =
      radius_j > 0.0 ? sphere_pair_constants(radius_i, sphere_mass(radius_i), radius_j, sphere_mass(radius_j), pair)
                     : sphere_wall_constants(radius_i, sphere_mass(radius_i), pair);
  law.complete(c);
  return c;
}

inline Wall floor_wall(bool adhesive) { return Wall{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0, adhesive}; }

// One unit sphere above the floor z = 0 with its surface `gap` above it, moving with `velocity`.
inline Simulation sphere_over_floor(const ContactModelSpec& spec, const Material& material, double gap,
                                    const Vec3& velocity, bool adhesive_wall, SimulationSettings settings = {}) {
  Particles p;
  p.add({0.0, 0.0, unit_radius + gap}, unit_radius, unit_density);
  p.velocity[0] = velocity;
  return Simulation(std::move(p), {material}, {floor_wall(adhesive_wall)}, spec, settings);
}

struct Impact {
  double restitution = 0.0;  // v_out / v_in, normal components
  double kinetic_before = 0.0;
  double kinetic_after = 0.0;
  EnergyBudget energy;  // after the sphere has left the wall
  std::int64_t contact_steps = 0;
  double time_step = 0.0;
};

// A sphere falls head-on onto the floor at `speed` and is followed until it has left the contact
// and moves away. The surface starts `lead` time steps of free flight above the floor (a fraction
// sets where the first contact step falls within a step).
inline Impact head_on_impact(const ContactModelSpec& spec, const Material& material, double speed,
                             SimulationSettings settings = {}, double lead = 0.5) {
  const Vec3 velocity{0.0, 0.0, -speed};
  const double dt = sphere_over_floor(spec, material, 1.0, velocity, false, settings).time_step();
  Simulation sim = sphere_over_floor(spec, material, lead * speed * dt, velocity, false, settings);
  Impact out;
  out.time_step = sim.time_step();
  out.kinetic_before = sim.energy().kinetic();
  bool touched = false;
  for (std::int64_t s = 0; s < 10'000'000; ++s) {
    sim.step();
    const bool in_contact = sim.contacts().size() > 0;
    if (in_contact) ++out.contact_steps;
    touched = touched || in_contact;
    if (touched && !in_contact && sim.particles().velocity[0].z > 0.0) {
      out.restitution = sim.particles().velocity[0].z / speed;
      out.energy = sim.energy();
      out.kinetic_after = out.energy.kinetic();
      return out;
    }
  }
  throw std::runtime_error("head_on_impact: the sphere did not leave the wall");
}

}  // namespace aerobreak::laws
