#include "engine/growth/diffusion_limited_aggregation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/cluster_contacts.hpp"
#include "engine/cluster/random_stream.hpp"
#include "engine/core/units.hpp"
#include "engine/dem/impact_placement.hpp"
#include "engine/dem/relaxation.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/growth/contact_clusters.hpp"
#include "engine/growth/random_placement.hpp"

namespace aerobreak {
namespace {

constexpr double kDiameter = 1.0;
constexpr double kMass = 1.0;

ContactModelSpec growth_model(const DiffusionLimitedParameters& p, const Material& material) {
  ContactModelSpec spec;
  spec.normal = NormalLaw::jkr;
  spec.separation = JkrSeparation::displacement;
  spec.tangential = p.tangential;
  spec.friction = p.friction;
  spec.rolling = p.sintering;
  spec.critical_rolling = p.critical_rolling;
  spec.twisting = p.sintering;
  if (p.damping_ratio > 0.0) {
    // Stiffness about equilibrium 3.6 F_c R* / a0^2 (eqs 2, 5), critical coefficient
    // 2 sqrt(k m*), and eta = 2 A E* a (eq 8) equal to the wanted share of it at a = a0 (one A
    // serves: the primaries are all alike).
    const ContactConstants c = primary_contact(material, spec, kDiameter, kMass);
    const double stiffness = 3.6 * c.pull_off_force * c.radius / (c.equilibrium_radius * c.equilibrium_radius);
    spec.damping = DampingLaw::viscoelastic;
    spec.dissipative_time =
        p.damping_ratio * 2.0 * std::sqrt(stiffness * c.mass) / (2.0 * c.modulus * c.equilibrium_radius);
  }
  return spec;
}

Particles primaries_at(const std::vector<Vec3>& positions, double density) {
  Particles particles;
  particles.reserve(positions.size());
  for (const Vec3& x : positions) particles.add(x, 0.5 * kDiameter, density);
  return particles;
}

// Runs the plain engine until one cluster is left; returns the steps taken.
std::int64_t grow(Simulation& sim, const DiffusionLimitedParameters& p,
                  const DiffusionLimitedProgressCallback& progress) {
  const std::size_t n = sim.particles().size();
  while (true) {
    const auto sizes = connected_component_sizes(n, contact_edges(sim));
    if (progress) {
      const std::vector<ContactCluster> components = contact_clusters(sim);
      progress({sim.step_count(), sim.time(), sizes.size(), sizes.front(), &components});
    }
    if (sizes.size() == 1) return sim.step_count();
    if (sim.step_count() >= p.max_steps)
      throw std::runtime_error("diffusion-limited aggregation: " + std::to_string(sizes.size()) +
                               " clusters remain (largest " + std::to_string(sizes.front()) + " of " +
                               std::to_string(n) + " primaries) after " + std::to_string(sim.step_count()) +
                               " steps; raise max_steps or the volume fraction");
    sim.run(std::min(p.check_interval, p.max_steps - sim.step_count()));
  }
}

double largest_tension(const Simulation& sim) {
  double tension = 0.0;
  sim.contacts().for_each([&](const ContactState& c) { tension = std::max(tension, -c.overlap); });
  return tension;
}

// The grown cluster, relaxed to JKR equilibrium (relax_cluster) and centred. Contacts the growth
// left in tension re-form in the relaxation through its bond gap.
Cluster relaxed(const ContactCluster& grown, double tension, const Material& material, const ContactModelSpec& spec,
                std::int64_t& steps) {
  RelaxationSettings settings;
  settings.bond_gap = std::max(settings.bond_gap, 1.001 * tension);
  const RelaxationResult r = relax_cluster(primaries_at(grown.position, material.density), {material}, spec, settings);
  if (!r.converged)
    throw std::runtime_error("diffusion-limited aggregation: the grown cluster did not relax within " +
                             std::to_string(r.steps) + " steps");
  steps = r.steps;
  Cluster cluster = cluster_from_particles(r.particles);
  const Vec3 centre = centre_of_mass(cluster);
  for (Vec3& x : cluster.position) x -= centre;
  return cluster;
}

}  // namespace

void DiffusionLimitedParameters::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("diffusion-limited aggregation: ") + what);
  };
  require(primary_count >= 1, "primary_count must be >= 1");
  require(volume_fraction > 0.0 && volume_fraction <= 0.3, "volume_fraction must lie in (0, 0.3]");
  require(gamma_over_kn > 0.0 && std::isfinite(gamma_over_kn), "gamma_over_kn must be > 0");
  require(poisson_ratio > -1.0 && poisson_ratio < 0.5, "poisson_ratio must lie in (-1, 0.5)");
  require(!sintering || critical_rolling > 0.0, "critical_rolling must be > 0 with sintering");
  require(friction >= 0.0, "friction must be >= 0");
  require(damping_ratio >= 0.0, "damping_ratio must be >= 0");
  require(bond_energy_over_kt > 0.0, "bond_energy_over_kt must be > 0");
  require(persistence_length > 0.0, "persistence_length must be > 0");
  require(steps_per_period > 0.0, "steps_per_period must be > 0");
  require(max_steps > 0, "max_steps must be > 0");
  require(check_interval > 0, "check_interval must be > 0");
  require(far_field.encounter_gap > 0.0, "far_field.encounter_gap must be > 0");
  require(far_field.release_gap >= far_field.encounter_gap, "far_field.release_gap must be >= encounter_gap");
  require(far_field.settle_time >= 0.0, "far_field.settle_time must be >= 0");
  require(far_field.step_fraction > 0.0 && far_field.step_fraction <= 0.5,
          "far_field.step_fraction must lie in (0, 0.5]");
  require(far_field.search_gap >= far_field.release_gap, "far_field.search_gap must be >= release_gap");
}

bool DiffusionLimitedParameters::rigid_far_field() const {
  return far_field_motion == FarField::rigid || (far_field_motion == FarField::rigid_when_sintered && sintering);
}

DiffusionLimitedResult grow_diffusion_limited(const DiffusionLimitedParameters& p, std::uint64_t seed,
                                              const DiffusionLimitedProgressCallback& progress) {
  p.validate();
  const Material material = reduced_material(p.gamma_over_kn, p.poisson_ratio);
  const ContactModelSpec spec = growth_model(p, material);
  DiffusionLimitedResult result;
  result.conditions =
      brownian_conditions(material, spec, kDiameter, kMass, p.bond_energy_over_kt, p.persistence_length);
  result.box_edge = cube_edge_for_volume_fraction(p.primary_count, kDiameter, p.volume_fraction);
  if (p.primary_count == 1) {
    result.cluster = {{Vec3{}}, {0.5 * kDiameter}};
    return result;
  }

  const PeriodicBox box{{result.box_edge, result.box_edge, result.box_edge}};
  RandomStream random(seed);
  SimulationSettings settings;
  settings.periodic = box;
  settings.steps_per_period = p.steps_per_period;
  // Like steps_per_period's halving: collisions at thermal speeds (bond energy 100 kT) must be
  // caught, not their adhesion loss resolved to 1 % (docs/MODEL.md 9.2).
  settings.steps_per_break_overlap = 0.0;
  // A Langevin stream apart from the placement's: counter-based on (seed, step, particle).
  settings.body.langevin = {result.conditions.temperature, result.conditions.drag_per_diameter,
                            seed ^ 0x6a09e667f3bcc909ULL};
  Particles primaries =
      primaries_at(random_sequential_positions(p.primary_count, box, kDiameter, random), material.density);
  Simulation sim(primaries, {material}, {}, spec, settings);
  result.time_step = sim.time_step();
  ContactCluster grown;
  double tension = 0.0;
  if (p.rigid_far_field()) {
    settings.time_step = sim.time_step();
    // Contacts inside a cluster that re-enters the engine are re-formed out to the break-off
    // overlap: a bond in tension stays bonded. A new contact between clusters still needs a touch
    // (they enter at encounter_gap, far beyond it), unless a rigid step overshot (overlaps).
    settings.initial_bond_gap = primary_contact(material, spec, kDiameter, kMass).break_overlap;
    const PrimaryBath bath{0.5 * kDiameter,
                           kMass,
                           primaries.inertia.front(),
                           result.conditions.drag,
                           result.conditions.drag * kDiameter * kDiameter / 3.0,
                           result.conditions.temperature};
    RigidFarFieldSettings far = p.far_field;
    far.engine_chunk = p.check_interval;
    far.max_steps = p.max_steps;
    const auto look = [&](const RigidFarFieldLook& l) {
      if (progress)
        progress({l.rigid_steps, l.time, l.clusters->size(), l.clusters->front().members.size(), l.clusters});
    };
    RigidFarFieldOutcome o = grow_with_rigid_far_field(primaries, material, spec, settings, bath, far, seed, look);
    result.steps = o.rigid_steps;
    result.time = o.time;
    result.contacts_broken = o.contacts_broken;
    result.engine_particle_steps = o.engine_particle_steps;
    result.encounters = o.encounters;
    result.overlaps = o.overlaps;
    grown = std::move(o.grown);
    tension = o.tension;
  } else {
    result.steps = grow(sim, p, progress);
    result.time = sim.time();
    result.contacts_broken = sim.pair_events().broken;
    result.engine_particle_steps = result.steps * static_cast<std::int64_t>(p.primary_count);
    grown = contact_clusters(sim).front();
    tension = largest_tension(sim);
  }
  result.contacts = grown.contacts;
  result.image_contacts = grown.image_contacts;
  result.cluster = relaxed(grown, tension, material, spec, result.relaxation_steps);
  return result;
}

Cluster diffusion_limited_aggregation(const DiffusionLimitedParameters& parameters, std::uint64_t seed,
                                      const DiffusionLimitedProgressCallback& progress) {
  return grow_diffusion_limited(parameters, seed, progress).cluster;
}

}  // namespace aerobreak
