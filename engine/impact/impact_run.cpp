#include "engine/impact/impact_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/cluster_contacts.hpp"
#include "engine/cluster/neighbour_order.hpp"
#include "engine/cluster/random_stream.hpp"
#include "engine/core/run_clock.hpp"
#include "engine/dem/impact_placement.hpp"
#include "engine/dem/relaxation.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/contact_scales.hpp"
#include "engine/impact/impact_measurement.hpp"
#include "engine/impact/settle.hpp"
#include "engine/io/cluster_library.hpp"
#include "engine/io/xyz.hpp"

namespace aerobreak {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Contacts live at the start of a run are the relaxed cluster's bonds: pairs whose surfaces are
// within this gap (in d) of touching, so that round-off in the coordinates cannot unbond them.
constexpr double kBondGap = 1e-6;

// Every primary of the case's material, index 0; the wall's material is index 1.
constexpr std::uint16_t kWallMaterial = 1;

// Diameter of the bounding sphere of the particles about their centre of mass.
double extent_of(const Particles& p) {
  const Vec3 centre = p.centre_of_mass();
  double extent = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    extent = std::max(extent, 2.0 * (norm(p.position[i] - centre) + p.radius[i]));
  return extent;
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

// Settle criterion (docs/IMPACT.md). The automatic window covers 50 contact periods and a fraction
// (a tenth unless the case says otherwise) of the time the cluster needs to cross its own extent
// at the normal impact speed.
void choose_settle_window(ImpactResult& r, double extent) {
  const ImpactCase& c = r.impact_case;
  const double normal_speed = -dot(r.impact_velocity, r.wall_normal);
  const double share_of_crossing = c.settle.extent_crossing_fraction * extent / normal_speed;
  r.quiet_window = c.settle.quiet_window > 0.0 ? c.settle.quiet_window
                                               : std::max(50.0 * r.time_step_estimate.period, share_of_crossing);
  if (!(r.quiet_window > 0.0) || !std::isfinite(r.quiet_window)) r.quiet_window = 1000.0 * r.time_step;
  r.rest_speed = c.settle.rest_speed_fraction * c.speed;
}

void tell(const std::function<void(const std::string&)>& log, const std::string& line) {
  if (log) log(line);
}

// Primaries that overlap by more than the contact laws' small-strain range (docs/MODEL.md 3.7:
// half the smaller radius) start the run far outside any law: refused, naming the first such pair.
void require_overlaps_in_range(const Cluster& cluster, const std::filesystem::path& file) {
  const double limit = StrainLimits{}.overlap_ratio;
  const auto deep = find_overlap_beyond(cluster, limit);
  if (!deep) return;
  char message[320];
  std::snprintf(message, sizeof message,
                "primaries %zu and %zu (counted from 0) overlap by %.6g d, more than %g of the smaller radius "
                "(%.6g d), the contact laws' small-strain range (docs/MODEL.md 3.7): no impact can start from it",
                deep->i, deep->j, deep->overlap, limit, deep->smaller_radius);
  throw CaseError({{"/cluster/file/path", file.string() + ": " + message}});
}

// A case's cluster file: a cluster library (HDF5, told by its signature), the named cluster or its
// only one, or an XYZ file; its primaries may overlap only within the small-strain range.
Cluster read_case_cluster(const ClusterSource& source) {
  Cluster cluster;
  if (!is_hdf5_file(source.file)) {
    cluster = read_xyz_cluster(source.file, source.default_radius);
  } else {
    const std::string name = source.library_name.empty() ? list_clusters(source.file).at(0) : source.library_name;
    cluster = read_cluster(source.file, name).cluster;
  }
  require_overlaps_in_range(cluster, source.file);
  return cluster;
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
    // Listed along their neighbours, as the generators list theirs: the pair loop then works on a
    // narrow band of particles, whatever order the file had (docs/PERFORMANCE.md).
    cluster = ordered_along_neighbours(read_case_cluster(c.cluster));
    tell(log, "read " + std::to_string(cluster.size()) + " primaries from " + c.cluster.file.string() +
                  " (listed along their neighbours)");
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
  settings.adaptive_time_step = c.adaptive_time_step;
  settings.steps_per_period = c.steps_per_period;
  settings.steps_per_break_overlap = c.steps_per_break_overlap;
  settings.speed_scale = c.speed;
  settings.initial_bond_gap = kBondGap;
  prepared.simulation = std::make_unique<Simulation>(
      place_for_impact(cluster, r.orientation, wall, c.gap, r.impact_velocity),
      std::vector<Material>{c.material, c.wall_material}, std::vector<Wall>{wall}, c.model, settings);
  const Simulation& sim = *prepared.simulation;
  r.time_step = sim.time_step();
  r.time_step_estimate = sim.time_step_estimate();
  r.adaptive_time_step = sim.adaptive_time_step();
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

ImpactSchedule impact_schedule(const ImpactResult& r, std::size_t particles) {
  ImpactSchedule s;
  s.check_interval = r.quiet_window / 20.0;
  s.snapshot_interval = r.impact_case.snapshot_interval;
  s.progress_steps = std::max<std::int64_t>(1, 1'000'000 / static_cast<std::int64_t>(particles));
  return s;
}

ElapsedTimes run_prepared_impact(PreparedImpact& prepared, SettleMonitor& monitor, const ImpactRunOptions& options) {
  ImpactResult& r = prepared.result;
  Simulation& sim = *prepared.simulation;
  const ImpactSchedule schedule = impact_schedule(r, sim.particles().size());
  SnapshotObserver snapshots(options.snapshot, schedule.snapshot_interval, sim.time());
  SettleObserver settle(monitor, schedule.check_interval, sim.time());
  snapshots.take(sim);
  monitor.update(sim);
  const RunClock clock;
  ProgressObserver progress(options.progress, options.progress_seconds, r.impact_case.time_limit,
                            schedule.progress_steps, sim.step_count());
  std::vector<StepObserver*> observers{&snapshots, &settle};
  if (options.progress) observers.push_back(&progress);
  run_observed(sim, r.impact_case.time_limit, observers);
  const ElapsedTimes times = clock.elapsed();
  snapshots.take(sim);
  r.snapshots = snapshots.taken();
  return times;
}

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
                        c.settle.stop_when_outcome_fixed, c.settle.follow_rigid_turn);
  const ElapsedTimes times = run_prepared_impact(prepared, monitor, options);
  measure_impact(prepared, monitor, times);
  return std::move(prepared.result);
}

}  // namespace aerobreak
