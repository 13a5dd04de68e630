#include "engine/dem/relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/contact/damping.hpp"
#include "engine/dem/simulation.hpp"

namespace aerobreak {
namespace {

// Constants of a contact between two of the largest spheres, as the normal law fills them.
ContactConstants typical_contact(const Particles& p, const Material& material, const ContactModelSpec& spec) {
  const std::size_t big = std::max_element(p.radius.begin(), p.radius.end()) - p.radius.begin();
  ContactConstants c =
      sphere_pair_constants(p.radius[big], p.mass[big], p.radius[big], p.mass[big], combine(material, material));
  make_contact_forces(spec, spec.normal)->complete(c);
  return c;
}

}  // namespace

RelaxationResult relax_cluster(Particles particles, const std::vector<Material>& materials,
                               const ContactModelSpec& model, const RelaxationSettings& settings) {
  if (particles.size() == 0) throw std::invalid_argument("relax: no particles");
  if (materials.empty()) throw std::invalid_argument("relax: no materials");
  ContactModelSpec spec;
  spec.normal = model.normal;
  spec.separation = model.separation;
  spec.tangential = false;

  if (model.normal == NormalLaw::hertz)
    throw std::invalid_argument("relax: a cluster without adhesion (Hertz law) has no equilibrium to relax to");
  const ContactConstants c = typical_contact(particles, materials[particles.material[0]], spec);
  // Energy scale of a bond: F_c times the overlap scale a0^2/R* (JKR: 2 6^(1/3) delta_c; DMT has
  // no delta_c).
  const double energy_scale = c.pull_off_force * c.equilibrium_radius * c.equilibrium_radius / c.radius;
  // Equilibrium stiffness of a JKR contact, dF/d(delta) at a = a0: 3.6 F_c R* / a0^2 (eqs 2, 5).
  const double stiffness = c.equilibrium_radius > 0.0
                               ? 3.6 * c.pull_off_force * c.radius / (c.equilibrium_radius * c.equilibrium_radius)
                               : c.hertz_coefficient * std::sqrt(c.radius);
  // Tsuji damping (eq 9) at the critical value about equilibrium for every contact, small or
  // large (tsuji_alpha_for_jkr_damping_ratio; for DMT the same alpha is 0.77 of critical).
  // Visco-elastic damping with one A, critical for the largest spheres, is over-critical by
  // (R*_large / R*)^(7/6) for smaller ones, and beyond the explicit stability limit
  // (eta dt/m* > 2) for the smallest ones of a strongly polydisperse cluster.
  spec.damping = DampingLaw::tsuji;
  spec.restitution = tsuji_restitution(tsuji_alpha_for_jkr_damping_ratio(1.0));

  for (auto& v : particles.velocity) v = {};
  for (auto& w : particles.angular_velocity) w = {};
  SimulationSettings run;
  run.initial_bond_gap = settings.bond_gap;
  run.speed_scale = std::sqrt(4.0 * energy_scale / c.mass);
  // Drag relaxation time of one contact period: zeta = m / tau, per unit diameter.
  const double period = 2.0 * std::numbers::pi * std::sqrt(c.mass / stiffness);
  run.body.langevin.drag_per_diameter = 2.0 * c.mass / period / (2.0 * c.radius * 2.0);
  Simulation sim(std::move(particles), materials, {}, spec, run);

  RelaxationResult result;
  const double limit = settings.kinetic_tolerance * energy_scale * static_cast<double>(sim.particles().size());
  const double force_scale = std::max(c.pull_off_force, 1e-300);
  const auto largest_force = [&] {
    double largest = 0.0;
    for (const Vec3& f : sim.particles().force) largest = std::max(largest, norm2(f));
    return std::sqrt(largest) / force_scale;
  };
  // Kinetic energy alone can be small while a heavily dragged network still creeps: both must be.
  while (sim.step_count() < settings.max_steps) {
    sim.run(500);
    if (sim.energy().kinetic() < limit && largest_force() < settings.force_tolerance) {
      result.converged = true;
      break;
    }
  }
  result.largest_force = largest_force();
  result.steps = sim.step_count();
  result.kinetic_per_particle = sim.energy().kinetic() / energy_scale / static_cast<double>(sim.particles().size());
  result.contacts = sim.contacts().size();
  result.contacts_broken = sim.pair_events().broken;
  result.particles = sim.particles();
  for (auto& v : result.particles.velocity) v = {};
  for (auto& w : result.particles.angular_velocity) w = {};
  result.particles.clear_forces();
  return result;
}

}  // namespace aerobreak
