#include "engine/impact/impact_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/settle.hpp"

namespace aerobreak {
namespace {

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

// The run's counters, as the simulation left them.
void record_run(PreparedImpact& prepared, const SettleMonitor& monitor, const ElapsedTimes& stepping) {
  ImpactResult& r = prepared.result;
  const Simulation& sim = *prepared.simulation;
  r.wall_clock_seconds = stepping.wall_seconds;
  r.cpu_seconds = stepping.cpu_seconds;
  r.steps = sim.step_count();
  r.simulated_time = sim.time();
  r.settled = monitor.settled();
  r.settled_by = monitor.rule();
  r.settled_at = monitor.settled_at();
  r.quiet_since = monitor.quiet_since();
  if (!r.settled) r.unsettled_reason = monitor.open_reason(sim);
  const double particle_steps = static_cast<double>(r.primaries) * static_cast<double>(r.steps);
  r.particle_steps_per_second = stepping.wall_seconds > 0.0 ? particle_steps / stepping.wall_seconds : 0.0;
  r.particle_steps_per_cpu_second = stepping.cpu_seconds > 0.0 ? particle_steps / stepping.cpu_seconds : 0.0;
  r.neighbor_builds = sim.neighbor_builds();
  r.step_history = sim.step_history();
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

// The final state: fragments of the final contact graph (settled: the judged state), outcome,
// restitution, compaction of the largest fragment, damage and the small-strain check.
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

std::vector<std::pair<std::uint32_t, std::uint32_t>> contact_pairs(const Simulation& sim) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  sim.contacts().for_each([&](const ContactState& c) {
    if (!c.with_wall) pairs.emplace_back(std::min(c.i, c.j), std::max(c.i, c.j));
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

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

void measure_impact(PreparedImpact& prepared, const SettleMonitor& monitor, const ElapsedTimes& stepping) {
  record_run(prepared, monitor, stepping);
  analyse_final_state(prepared, monitor);
}

}  // namespace aerobreak
