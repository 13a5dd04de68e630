#include "engine/impact/impact_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
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
  return s;
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

ImpactResult run_impact(const ImpactCase& c, const ImpactRunOptions& options) {
  ImpactResult r;
  r.impact_case = c;
  const Particles cluster = prepare_cluster(c, r.relaxation, options.log);
  const std::size_t n = cluster.size();
  r.primaries = n;

  Wall wall;
  wall.point = {0.0, 0.0, 0.0};
  wall.normal = {0.0, 0.0, 1.0};
  wall.material = kWallMaterial;
  wall.adhesive = c.wall_adhesive;
  r.wall_normal = wall.normal;
  r.orientation = impact_orientation(c);
  r.impact_velocity = impact_velocity(c);

  SimulationSettings settings;
  settings.time_step = c.time_step;
  settings.steps_per_period = c.steps_per_period;
  settings.steps_per_break_overlap = c.steps_per_break_overlap;
  settings.speed_scale = c.speed;
  settings.initial_bond_gap = kBondGap;
  Simulation sim(place_for_impact(cluster, r.orientation, wall, c.gap, r.impact_velocity), {c.material, c.wall_material},
                 {wall}, c.model, settings);
  r.time_step = sim.time_step();
  r.time_step_estimate = sim.time_step_estimate();
  r.initial_energy = sim.energy();
  r.initial_contacts = sim.contacts().size();  // no wall contact at the start: the cluster is `gap` above
  // The engine counts the bonds formed when the run starts as made: events are counted from here.
  const ContactEvents pair_start = sim.pair_events();
  const ContactEvents wall_start = sim.wall_events();
  double total_mass = 0.0;
  for (double m : sim.particles().mass) total_mass += m;
  r.impact_kinetic_energy = 0.5 * total_mass * norm2(r.impact_velocity);

  std::vector<std::uint32_t> everyone(n);
  for (std::uint32_t i = 0; i < n; ++i) everyone[i] = i;
  r.before = shape_of(sim.particles(), everyone, r.initial_contacts);

  // Settle criterion (docs/IMPACT.md). The automatic quiet window covers 50 contact periods and a
  // tenth of the time the cluster needs to cross its own extent at the normal impact speed.
  const double normal_speed = -dot(r.impact_velocity, wall.normal);
  double extent = 0.0;  // diameter of the cluster's bounding sphere about its centre of mass
  {
    const Particles& p = sim.particles();
    Vec3 centre;
    for (std::size_t i = 0; i < n; ++i) centre += p.mass[i] * p.position[i];
    centre = centre / total_mass;
    for (std::size_t i = 0; i < n; ++i) extent = std::max(extent, 2.0 * (norm(p.position[i] - centre) + p.radius[i]));
  }
  r.quiet_window = c.settle.quiet_window > 0.0
                       ? c.settle.quiet_window
                       : std::max(50.0 * r.time_step_estimate.period, 0.1 * extent / normal_speed);
  if (!(r.quiet_window > 0.0) || !std::isfinite(r.quiet_window)) r.quiet_window = 1000.0 * r.time_step;
  r.rest_speed = c.settle.rest_speed_fraction * c.speed;
  SettleMonitor monitor(r.quiet_window, r.rest_speed);

  const double dt = sim.time_step();
  const auto limit_steps = static_cast<std::int64_t>(std::ceil(c.time_limit / dt - 1e-9));
  const std::int64_t check_steps = std::max<std::int64_t>(1, static_cast<std::int64_t>(r.quiet_window / dt / 20.0));
  const std::int64_t snapshot_steps =
      c.snapshot_interval > 0.0 ? std::max<std::int64_t>(1, std::llround(c.snapshot_interval / dt)) : 0;
  // Chunks between progress checks: about 1e6 particle-steps, and never past a check or snapshot.
  const std::int64_t progress_steps = std::max<std::int64_t>(1, 1'000'000 / static_cast<std::int64_t>(n));

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
    const std::int64_t target =
        std::min({limit_steps, next_check, next_snapshot, s + progress_steps});
    sim.run(target - s);
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
      const double elapsed = seconds_since(start);
      ImpactProgress progress;
      progress.time = sim.time();
      progress.time_limit = c.time_limit;
      progress.steps = sim.step_count();
      progress.steps_per_second = static_cast<double>(sim.step_count()) / elapsed;
      progress.particle_steps_per_second = progress.steps_per_second * static_cast<double>(n);
      sim.contacts().for_each([&](const ContactState& contact) {
        if (contact.with_wall)
          ++progress.wall_contacts;
        else
          ++progress.contacts;
      });
      progress.fragments = find_fragments(sim).fragments.size();
      progress.kinetic_energy = sim.energy().kinetic();
      options.progress(progress);
    }
  }
  r.wall_clock_seconds = seconds_since(start);
  snapshot();

  r.steps = sim.step_count();
  r.simulated_time = sim.time();
  r.settled = monitor.settled();
  r.settled_at = monitor.settled_at();
  r.quiet_since = monitor.quiet_since();
  if (!r.settled) r.unsettled_reason = monitor.last_reason();
  r.particle_steps_per_second =
      r.wall_clock_seconds > 0.0 ? static_cast<double>(n) * static_cast<double>(r.steps) / r.wall_clock_seconds : 0.0;
  r.neighbor_builds = sim.neighbor_builds();
  r.pair_events = sim.pair_events();
  r.pair_events.made -= pair_start.made;
  r.pair_events.broken -= pair_start.broken;
  r.wall_events = sim.wall_events();
  r.wall_events.made -= wall_start.made;
  r.wall_events.broken -= wall_start.broken;
  r.final_energy = sim.energy();

  // Final analysis: fragments of the final contact graph.
  // Settled: the judged state is the final one (the run stopped right after the judgement).
  const FragmentAnalysis end = r.settled ? monitor.judged_fragments() : find_fragments(sim);
  r.fragments = end.fragments;
  if (r.settled) r.fragment_mean_velocity = monitor.judged_mean_velocities();
  std::size_t largest_contacts = 0;
  sim.contacts().for_each([&](const ContactState& contact) {
    if (contact.with_wall) {
      ++r.final_wall_contacts;
      return;
    }
    ++r.final_contacts;
    if (end.fragment_of[contact.i] == 0) ++largest_contacts;
  });
  r.classification = classify(r.fragments, r.settled, c.largest_fragment_share);

  // Restitution from the largest fragment's velocity averaged over the settling quiet window (a
  // fragment stuck to the wall still vibrates), or its velocity at the end if it never settled.
  const Fragment& largest = r.fragments.front();
  const Vec3 rebound = r.settled ? r.fragment_mean_velocity.front() : largest.velocity;
  const double impact_normal = dot(r.impact_velocity, wall.normal);  // < 0
  r.restitution_normal = -dot(rebound, wall.normal) / impact_normal;
  const Vec3 tangential = r.impact_velocity - impact_normal * wall.normal;
  const double tangential_speed = norm(tangential);
  r.restitution_tangential = tangential_speed > 1e-12 * c.speed
                                 ? dot(rebound, tangential) / (tangential_speed * tangential_speed)
                                 : std::numeric_limits<double>::quiet_NaN();
  double on_wall = 0.0;
  for (const Fragment& f : r.fragments) {
    if (f.on_wall()) on_wall += f.mass;
    r.fragment_translational_kinetic += 0.5 * f.mass * norm2(f.velocity);
  }
  r.mass_fraction_on_wall = on_wall / total_mass;

  std::vector<std::uint32_t> members;
  members.reserve(largest.size);
  for (std::uint32_t i = 0; i < n; ++i)
    if (end.fragment_of[i] == 0) members.push_back(i);
  r.after = shape_of(sim.particles(), members, largest_contacts);
  return r;
}

}  // namespace aerobreak
