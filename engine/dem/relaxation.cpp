#include "engine/dem/relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/contact/damping.hpp"
#include "engine/dem/simulation.hpp"

namespace aerobreak {
namespace {

// Constants of a contact between two spheres like particle i (its radius, mass and material), as
// the normal law fills them.
ContactConstants like_pair(const Particles& p, std::size_t i, const std::vector<Material>& materials,
                           const ContactForces& law) {
  const Material& material = materials.at(p.material[i]);
  ContactConstants c =
      sphere_pair_constants(p.radius[i], p.mass[i], p.radius[i], p.mass[i], combine(material, material));
  law.complete(c);
  return c;
}

// Energy scale of a bond: F_c times the overlap scale a0^2/R* (JKR: 2 6^(1/3) delta_c; DMT has
// no delta_c).
double bond_energy(const ContactConstants& c) {
  return c.pull_off_force * c.equilibrium_radius * c.equilibrium_radius / c.radius;
}

// Each particle's own force and energy scales: F_c and the bond energy of two spheres like it. A
// small sphere's bonds are weaker than a large one's (F_c ~ R*), so it is judged on its own scale.
struct OwnScales {
  std::vector<double> force;
  std::vector<double> energy;
};

OwnScales own_scales(const Particles& p, const std::vector<Material>& materials, const ContactForces& law) {
  OwnScales own;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const ContactConstants c = like_pair(p, i, materials, law);
    own.force.push_back(std::max(c.pull_off_force, 1e-300));
    own.energy.push_back(std::max(bond_energy(c), 1e-300));
  }
  return own;
}

// How far from rest the cluster is, each particle measured on its own scales.
struct Residual {
  double kinetic_per_particle = 0.0;  // mean of (kinetic energy / own bond energy)
  double largest_force = 0.0;         // largest net force / own F_c
};

Residual residual(const Particles& p, const OwnScales& own) {
  Residual r;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double kinetic = 0.5 * (p.mass[i] * norm2(p.velocity[i]) + p.inertia[i] * norm2(p.angular_velocity[i]));
    r.kinetic_per_particle += kinetic / own.energy[i];
    r.largest_force = std::max(r.largest_force, norm(p.force[i]) / own.force[i]);
  }
  r.kinetic_per_particle /= static_cast<double>(p.size());
  return r;
}

}  // namespace

RelaxationResult relax_cluster(Particles particles, const std::vector<Material>& materials,
                               const ContactModelSpec& model, const RelaxationSettings& settings) {
  if (particles.size() == 0) throw std::invalid_argument("relax: no particles");
  if (materials.empty()) throw std::invalid_argument("relax: no materials");
  if (model.normal == NormalLaw::hertz)
    throw std::invalid_argument("relax: a cluster without adhesion (Hertz law) has no equilibrium to relax to");
  ContactModelSpec spec;
  spec.normal = model.normal;
  spec.separation = model.separation;
  spec.tangential = false;
  // Tsuji damping (eq 9) at the critical value about equilibrium for every contact, small or
  // large (tsuji_alpha_for_jkr_damping_ratio; for DMT the same alpha is 0.77 of critical).
  // Visco-elastic damping with one A, critical for the largest spheres, is over-critical by
  // (R*_large / R*)^(7/6) for smaller ones, and beyond the explicit stability limit
  // (eta dt/m* > 2) for the smallest ones of a strongly polydisperse cluster.
  spec.damping = DampingLaw::tsuji;
  spec.restitution = tsuji_restitution(tsuji_alpha_for_jkr_damping_ratio(1.0));

  const auto law = make_contact_forces(spec, spec.normal);
  const OwnScales own = own_scales(particles, materials, *law);
  // The largest spheres set the speed scale and the drag.
  const std::size_t big = std::max_element(particles.radius.begin(), particles.radius.end()) - particles.radius.begin();
  const ContactConstants c = like_pair(particles, big, materials, *law);
  // Equilibrium stiffness of a JKR contact, dF/d(delta) at a = a0: 3.6 F_c R* / a0^2 (eqs 2, 5);
  // without adhesion (w = 0) the Hertz scale K sqrt(R*).
  const double stiffness = c.equilibrium_radius > 0.0
                               ? 3.6 * c.pull_off_force * c.radius / (c.equilibrium_radius * c.equilibrium_radius)
                               : c.hertz_coefficient * std::sqrt(c.radius);

  for (auto& v : particles.velocity) v = {};
  for (auto& w : particles.angular_velocity) w = {};
  SimulationSettings run;
  run.initial_bond_gap = settings.bond_gap;
  run.speed_scale = std::sqrt(4.0 * bond_energy(c) / c.mass);
  // Overdamped: where the contacts end up matters, not the energy an adhesion loop loses on the
  // way, so the step need not resolve the break overlap (docs/MODEL.md 9.2).
  run.steps_per_break_overlap = 0.0;
  // Drag relaxation time of one contact period: zeta = m / tau, per unit diameter.
  const double period = 2.0 * std::numbers::pi * std::sqrt(c.mass / stiffness);
  run.body.langevin.drag_per_diameter = 2.0 * c.mass / period / (2.0 * c.radius * 2.0);
  Simulation sim(std::move(particles), materials, {}, spec, run);

  RelaxationResult result;
  // Kinetic energy alone can be small while a heavily dragged network still creeps: both must be.
  Residual r = residual(sim.particles(), own);
  while (sim.step_count() < settings.max_steps) {
    sim.run(500);
    r = residual(sim.particles(), own);
    if (r.kinetic_per_particle < settings.kinetic_tolerance && r.largest_force < settings.force_tolerance) {
      result.converged = true;
      break;
    }
  }
  result.largest_force = r.largest_force;
  result.kinetic_per_particle = r.kinetic_per_particle;
  result.steps = sim.step_count();
  result.contacts = sim.contacts().size();
  result.contacts_broken = sim.pair_events().broken;
  result.particles = sim.particles();
  for (auto& v : result.particles.velocity) v = {};
  for (auto& w : result.particles.angular_velocity) w = {};
  result.particles.clear_forces();
  return result;
}

}  // namespace aerobreak
