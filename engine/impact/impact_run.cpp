#include "engine/impact/impact_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/random_stream.hpp"
#include "engine/dem/impact_placement.hpp"
#include "engine/dem/relaxation.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/settle.hpp"
#include "engine/io/cluster_library.hpp"
#include "engine/io/xyz.hpp"

namespace aerobreak {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Contacts live at the start of a run are the relaxed cluster's bonds: pairs whose surfaces are
// within this gap (in d) of touching, so that round-off in the coordinates cannot unbond them.
constexpr double kBondGap = 1e-6;

// Every primary of the case's material, index 0; the wall's material is index 1.
constexpr std::uint16_t kWallMaterial = 1;

ClusterShape shape_of(const Particles& p, const std::vector<std::uint32_t>& members, std::size_t contacts) {
  Cluster c;
  c.position.reserve(members.size());
  c.radius.reserve(members.size());
  for (std::uint32_t i : members) {
    c.position.push_back(p.position[i]);
    c.radius.push_back(p.radius[i]);
  }
  ClusterShape s;
  s.primaries = members.size();
  if (members.empty()) return s;
  s.radius_of_gyration = radius_of_gyration(c);
  s.fractal_dimension = mass_radius_dimension(c);
  s.coordination = 2.0 * static_cast<double>(contacts) / static_cast<double>(members.size());
  s.filling_factor = members.size() > 1 ? filling_factor(c) : std::numeric_limits<double>::quiet_NaN();
  return s;
}

// Diameter of the bounding sphere of the particles about their centre of mass.
double extent_of(const Particles& p) {
  const Vec3 centre = p.centre_of_mass();
  double extent = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) extent = std::max(extent, 2.0 * (norm(p.position[i] - centre) + p.radius[i]));
  return extent;
}

// The particle-particle contacts of a simulation as sorted pairs (i < j).
std::vector<std::pair<std::uint32_t, std::uint32_t>> contact_pairs(const Simulation& sim) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  sim.contacts().for_each([&](const ContactState& c) {
    if (!c.with_wall) pairs.emplace_back(std::min(c.i, c.j), std::max(c.i, c.j));
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// How many of the sorted pairs `before` are missing from the sorted pairs `after`.
std::size_t missing_from(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& before,
                         const std::vector<std::pair<std::uint32_t, std::uint32_t>>& after) {
  std::size_t missing = 0;
  auto found = after.begin();
  for (const auto& pair : before) {
    found = std::lower_bound(found, after.end(), pair);
    if (found == after.end() || *found != pair) ++missing;
  }
  return missing;
}

// The contact energies of two primaries of diameter d = 1 (the geometric mean of a polydisperse
// cluster) of the case's material, under the case's normal law.
ContactEnergies primary_contact_energies(const ImpactCase& c) {
  const MaterialTable materials({c.material});
  const double mass = c.material.density * std::numbers::pi / 6.0;
  const auto law = make_contact_forces(c.model, c.model.normal);
  return contact_energies(*law, sphere_pair_constants(0.5, mass, 0.5, mass, materials.pair(0, 0)),
                          c.model.rolling ? c.model.critical_rolling : 0.0);
}

Wall impact_wall(const ImpactCase& c) {
  Wall wall;
  wall.point = {0.0, 0.0, 0.0};
  wall.normal = {0.0, 0.0, 1.0};
  wall.material = kWallMaterial;
  wall.adhesive = c.wall_adhesive;
  return wall;
}

// Settle criterion (docs/IMPACT.md). The automatic window covers 50 contact periods and a tenth
// of the time the cluster needs to cross its own extent at the normal impact speed.
void choose_settle_window(ImpactResult& r, double extent) {
  const ImpactCase& c = r.impact_case;
  const double normal_speed = -dot(r.impact_velocity, r.wall_normal);
  r.quiet_window = c.settle.quiet_window > 0.0
                       ? c.settle.quiet_window
                       : std::max(50.0 * r.time_step_estimate.period, 0.1 * extent / normal_speed);
  if (!(r.quiet_window > 0.0) || !std::isfinite(r.quiet_window)) r.quiet_window = 1000.0 * r.time_step;
  r.rest_speed = c.settle.rest_speed_fraction * c.speed;
}

void tell(const std::function<void(const std::string&)>& log, const std::string& line) {
  if (log) log(line);
}

// A case's cluster file: a cluster library (HDF5, told by its signature), the named cluster or its
// only one, or an XYZ file.
Cluster read_case_cluster(const ClusterSource& source) {
  if (!is_hdf5_file(source.file)) return read_xyz_cluster(source.file, source.default_radius);
  const std::string name = source.library_name.empty() ? list_clusters(source.file).at(0) : source.library_name;
  return read_cluster(source.file, name).cluster;
}

}  // namespace

Rotation impact_orientation(const ImpactCase& c) { return RandomStream(c.orientation_seed).rotation(); }

Vec3 impact_velocity(const ImpactCase& c) {
  const double angle = c.angle_degrees * std::numbers::pi / 180.0;
  // Towards a wall of normal +z, tilted into +x by the impact angle.
  return {c.speed * std::sin(angle), 0.0, -c.speed * std::cos(angle)};
}

Particles prepare_cluster(const ImpactCase& c, RelaxationSummary& relaxation,
                          const std::function<void(const std::string&)>& log) {
  Cluster cluster;
  if (c.cluster.kind == ClusterSource::Kind::generated) {
    const auto start = Clock::now();
    cluster = generate_cluster(c.cluster.generator);
    tell(log, "built a " + c.cluster.generator.method + " cluster of " + std::to_string(cluster.size()) +
                  " primaries in " + std::to_string(seconds_since(start)) + " s");
  } else {
    cluster = read_case_cluster(c.cluster);
    tell(log, "read " + std::to_string(cluster.size()) + " primaries from " + c.cluster.file.string());
  }
  if (cluster.size() == 0) throw std::invalid_argument("impact: the cluster has no primaries");
  Particles particles = particles_from_cluster(cluster, c.material.density, 0);

  relaxation = {};
  if (c.cluster.relax && c.model.normal != NormalLaw::hertz && particles.size() > 1) {
    const auto start = Clock::now();
    RelaxationResult relaxed = relax_cluster(std::move(particles), {c.material}, c.model);
    relaxation.performed = true;
    relaxation.converged = relaxed.converged;
    relaxation.steps = relaxed.steps;
    relaxation.contacts = relaxed.contacts;
    relaxation.contacts_broken = relaxed.contacts_broken;
    relaxation.wall_clock_seconds = seconds_since(start);
    tell(log, std::string("relaxed the cluster in ") + std::to_string(relaxed.steps) + " steps (" +
                  std::to_string(relaxation.wall_clock_seconds) + " s, " +
                  (relaxed.converged ? "converged" : "NOT converged") + ", " + std::to_string(relaxed.contacts) +
                  " contacts, " + std::to_string(relaxed.contacts_broken) + " broken)");
    particles = std::move(relaxed.particles);
  }
  return particles;
}

PreparedImpact::PreparedImpact() = default;
PreparedImpact::PreparedImpact(PreparedImpact&&) noexcept = default;
PreparedImpact::~PreparedImpact() = default;

PreparedImpact prepare_impact(const ImpactCase& c, const ImpactRunOptions& options) {
  PreparedImpact prepared;
  ImpactResult& r = prepared.result;
  r.impact_case = c;
  const Particles cluster = prepare_cluster(c, r.relaxation, options.log);
  r.primaries = cluster.size();

  const Wall wall = impact_wall(c);
  r.wall_normal = wall.normal;
  r.orientation = impact_orientation(c);
  r.impact_velocity = impact_velocity(c);

  SimulationSettings settings;
  settings.time_step = c.time_step;
  settings.steps_per_period = c.steps_per_period;
  settings.steps_per_break_overlap = c.steps_per_break_overlap;
  settings.speed_scale = c.speed;
  settings.initial_bond_gap = kBondGap;
  prepared.simulation =
      std::make_unique<Simulation>(place_for_impact(cluster, r.orientation, wall, c.gap, r.impact_velocity),
                                   std::vector<Material>{c.material, c.wall_material}, std::vector<Wall>{wall}, c.model,
                                   settings);
  const Simulation& sim = *prepared.simulation;
  r.time_step = sim.time_step();
  r.time_step_estimate = sim.time_step_estimate();
  r.initial_energy = sim.energy();
  prepared.initial_contacts = contact_pairs(sim);
  r.initial_contacts = prepared.initial_contacts.size();  // no wall contact yet: the cluster is `gap` above
  prepared.pair_start = sim.pair_events();
  prepared.wall_start = sim.wall_events();
  double total_mass = 0.0;
  for (double m : sim.particles().mass) total_mass += m;
  r.impact_kinetic_energy = 0.5 * total_mass * norm2(r.impact_velocity);
  r.contact_energies = primary_contact_energies(c);
  r.energy_groups = energy_groups(r.impact_kinetic_energy, r.initial_contacts, r.contact_energies);

  std::vector<std::uint32_t> everyone(r.primaries);
  std::iota(everyone.begin(), everyone.end(), 0u);
  r.before = shape_of(sim.particles(), everyone, r.initial_contacts);
  choose_settle_window(r, extent_of(sim.particles()));
  return prepared;
}

namespace {

ImpactProgress progress_of(const Simulation& sim, double time_limit, double elapsed) {
  ImpactProgress progress;
  progress.time = sim.time();
  progress.time_limit = time_limit;
  progress.steps = sim.step_count();
  progress.steps_per_second = static_cast<double>(sim.step_count()) / elapsed;
  progress.particle_steps_per_second = progress.steps_per_second * static_cast<double>(sim.particles().size());
  sim.contacts().for_each([&](const ContactState& contact) {
    if (contact.with_wall)
      ++progress.wall_contacts;
    else
      ++progress.contacts;
  });
  progress.fragments = find_fragments(sim).fragments.size();
  progress.kinetic_energy = sim.energy().kinetic();
  return progress;
}

// Steps the simulation until the monitor finds the outcome settled or the time limit comes,
// writing snapshots and progress on the way; returns the wall-clock seconds it took.
double run_until_settled(PreparedImpact& prepared, SettleMonitor& monitor, const ImpactRunOptions& options) {
  ImpactResult& r = prepared.result;
  Simulation& sim = *prepared.simulation;
  const ImpactCase& c = r.impact_case;
  const double dt = sim.time_step();
  const auto limit_steps = static_cast<std::int64_t>(std::ceil(c.time_limit / dt - 1e-9));
  const std::int64_t check_steps = std::max<std::int64_t>(1, static_cast<std::int64_t>(r.quiet_window / dt / 20.0));
  const std::int64_t snapshot_steps =
      c.snapshot_interval > 0.0 ? std::max<std::int64_t>(1, std::llround(c.snapshot_interval / dt)) : 0;
  // Chunks between progress checks: about 1e6 particle-steps, and never past a check or snapshot.
  const std::int64_t progress_steps =
      std::max<std::int64_t>(1, 1'000'000 / static_cast<std::int64_t>(sim.particles().size()));

  std::int64_t last_snapshot = -1;
  auto snapshot = [&] {
    if (!options.snapshot || last_snapshot == sim.step_count()) return;
    options.snapshot(sim);
    last_snapshot = sim.step_count();
    ++r.snapshots;
  };
  snapshot();
  monitor.update(sim);

  const auto start = Clock::now();
  auto last_progress = start;
  std::int64_t next_check = check_steps;
  std::int64_t next_snapshot = snapshot_steps > 0 ? snapshot_steps : limit_steps + 1;
  while (sim.step_count() < limit_steps) {
    const std::int64_t s = sim.step_count();
    sim.run(std::min({limit_steps, next_check, next_snapshot, s + progress_steps}) - s);
    if (sim.step_count() == next_snapshot) {
      snapshot();
      next_snapshot += snapshot_steps;
    }
    if (sim.step_count() == next_check) {
      next_check += check_steps;
      if (monitor.update(sim)) break;
    }
    if (options.progress && seconds_since(last_progress) >= options.progress_seconds) {
      last_progress = Clock::now();
      options.progress(progress_of(sim, c.time_limit, seconds_since(start)));
    }
  }
  const double seconds = seconds_since(start);
  snapshot();
  return seconds;
}

// The run's counters, as the simulation left them.
void record_run(PreparedImpact& prepared, const SettleMonitor& monitor, double seconds) {
  ImpactResult& r = prepared.result;
  const Simulation& sim = *prepared.simulation;
  r.wall_clock_seconds = seconds;
  r.steps = sim.step_count();
  r.simulated_time = sim.time();
  r.settled = monitor.settled();
  r.settled_by = monitor.rule();
  r.settled_at = monitor.settled_at();
  r.quiet_since = monitor.quiet_since();
  if (!r.settled) r.unsettled_reason = monitor.open_reason(sim);
  r.particle_steps_per_second =
      seconds > 0.0 ? static_cast<double>(r.primaries) * static_cast<double>(r.steps) / seconds : 0.0;
  r.neighbor_builds = sim.neighbor_builds();
  r.pair_events = sim.pair_events();
  r.pair_events.made -= prepared.pair_start.made;
  r.pair_events.broken -= prepared.pair_start.broken;
  r.wall_events = sim.wall_events();
  r.wall_events.made -= prepared.wall_start.made;
  r.wall_events.broken -= prepared.wall_start.broken;
  r.final_energy = sim.energy();
}

// Restitution of the largest fragment: v_n after over |v_n| before, and along the impact's tangent.
void measure_restitution(ImpactResult& r) {
  r.rebound_velocity = r.fragment_final_velocity.front();
  const double impact_normal = dot(r.impact_velocity, r.wall_normal);  // < 0
  r.restitution_normal = -dot(r.rebound_velocity, r.wall_normal) / impact_normal;
  const Vec3 tangential = r.impact_velocity - impact_normal * r.wall_normal;
  const double tangential_speed = norm(tangential);
  r.restitution_tangential = tangential_speed > 1e-12 * r.impact_case.speed
                                 ? dot(r.rebound_velocity, tangential) / (tangential_speed * tangential_speed)
                                 : std::numeric_limits<double>::quiet_NaN();
}

// The final state: fragments of the final contact graph (settled: the judged state, which is the
// final one, the run having stopped right after the judgement), outcome, restitution, compaction
// of the largest fragment, damage and the small-strain check.
void analyse_final_state(PreparedImpact& prepared, const SettleMonitor& monitor) {
  ImpactResult& r = prepared.result;
  const Simulation& sim = *prepared.simulation;
  const FragmentAnalysis end = r.settled ? monitor.judged_fragments() : find_fragments(sim);
  r.fragments = end.fragments;
  if (r.settled) r.fragment_mean_velocity = monitor.judged_mean_velocities();
  r.fragment_final_velocity = r.fragment_mean_velocity;
  if (!r.settled)
    for (const Fragment& f : r.fragments) r.fragment_final_velocity.push_back(f.velocity);
  r.classification =
      classify(fates_of(r.fragments, r.fragment_final_velocity, r.wall_normal), r.settled, r.impact_case.thresholds);
  measure_restitution(r);

  const auto final_contacts = contact_pairs(sim);
  r.final_contacts = final_contacts.size();
  r.final_wall_contacts = sim.contacts().size() - final_contacts.size();
  r.initial_contacts_broken = missing_from(prepared.initial_contacts, final_contacts);
  std::size_t largest_contacts = 0;
  for (const auto& [i, j] : final_contacts)
    if (end.fragment_of[i] == 0) ++largest_contacts;
  for (const Fragment& f : r.fragments) r.fragment_translational_kinetic += 0.5 * f.mass * norm2(f.velocity);

  std::vector<std::uint32_t> members;
  members.reserve(r.fragments.front().size);
  for (std::uint32_t i = 0; i < sim.particles().size(); ++i)
    if (end.fragment_of[i] == 0) members.push_back(i);
  r.after = shape_of(sim.particles(), members, largest_contacts);

  DeepestOverlaps deepest;
  if (r.initial_contacts + r.pair_events.made > 0) deepest.pair = sim.pair_events().deepest_overlap_ratio;
  if (r.wall_events.made > 0) deepest.wall = sim.wall_events().deepest_overlap_ratio;
  r.validity = check_small_strain(deepest, sim.particles(), sim.materials(), sim.walls().front(), sim.model());
}

}  // namespace

ImpactResult run_impact(const ImpactCase& c, const ImpactRunOptions& options) {
  PreparedImpact prepared = prepare_impact(c, options);
  if (options.log) {
    const std::string setup = describe_setup(prepared.result);
    for (std::size_t begin = 0, end; begin < setup.size(); begin = end + 1) {
      end = setup.find('\n', begin);
      options.log(setup.substr(begin, end - begin));
    }
  }
  SettleMonitor monitor(prepared.result.quiet_window, prepared.result.rest_speed, c.thresholds,
                        c.settle.stop_when_outcome_fixed);
  const double seconds = run_until_settled(prepared, monitor, options);
  record_run(prepared, monitor, seconds);
  analyse_final_state(prepared, monitor);
  return std::move(prepared.result);
}

}  // namespace aerobreak
