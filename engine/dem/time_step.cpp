#include "engine/dem/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <set>
#include <stdexcept>

namespace aerobreak {
namespace {

// A contact the run may reach: its constants, the fastest approach speed and the law it uses.
struct Probe {
  ContactConstants constants;
  double speed;
  const ContactForces* law;
  bool between_particles;  // (a single particle's pair probe only bounds the stiffness)
};

// The laws a run's probes use, kept alive while the probes are evaluated.
struct ProbeSet {
  std::vector<std::unique_ptr<ContactForces>> laws;
  std::vector<Probe> probes;
};

// Deepest overlap reached when the contact absorbs `energy`: bisection on the normal law's
// stored energy, which grows monotonically with the overlap on the loading branch.
double overlap_for_energy(const ContactForces& law, const ContactConstants& c, double energy) {
  double low = 0.0;
  double high = 2.0 * c.radius;
  for (int k = 0; k < 200 && law.normal_response(high, c).energy < energy; ++k) high *= 2.0;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (low + high);
    (law.normal_response(mid, c).energy < energy ? low : high) = mid;
  }
  return high;
}

double normal_stiffness(const ContactForces& law, const ContactConstants& c, double overlap) {
  const double h = 1e-6 * std::max(overlap, c.radius * 1e-6);
  return (law.normal_response(overlap + h, c).force - law.normal_response(overlap - h, c).force) / (2.0 * h);
}

// The spheres of smallest and largest (radius, mass) with every pair of materials present, at
// 2 v_max against each other and at v_max against each wall.
ProbeSet probes_of(const Particles& p, const MaterialTable& materials, const std::vector<Wall>& walls,
                   const ContactModelSpec& spec, double max_speed) {
  std::set<std::uint16_t> present(p.material.begin(), p.material.end());
  std::vector<std::pair<double, double>> spheres;  // radius, mass
  for (std::size_t i = 0; i < p.size(); ++i) spheres.push_back({p.radius[i], p.mass[i]});
  const auto [small, large] = std::minmax_element(spheres.begin(), spheres.end());

  ProbeSet set;
  set.laws.push_back(make_contact_forces(spec, spec.normal));
  for (auto a : present)
    for (auto b : present)
      for (auto u : {small, large})
        for (auto v : {small, large}) {
          Probe probe{sphere_pair_constants(u->first, u->second, v->first, v->second, materials.pair(a, b)),
                      2.0 * max_speed, set.laws.front().get(), true};
          probe.law->complete(probe.constants);
          set.probes.push_back(probe);
        }
  for (const Wall& wall : walls) {
    set.laws.push_back(make_contact_forces(spec, wall.adhesive ? spec.normal : NormalLaw::hertz));
    for (auto a : present)
      for (auto u : {small, large}) {
        Probe probe{sphere_wall_constants(u->first, u->second, materials.pair(a, wall.material)), max_speed,
                    set.laws.back().get(), false};
        probe.law->complete(probe.constants);
        set.probes.push_back(probe);
      }
  }
  return set;
}

struct Stiffest {
  double stiffness = 0.0;
  double deepest = 0.0;
};

// The stiffest mode of a probe at its deepest overlap and at equilibrium.
Stiffest stiffest_mode(const Probe& probe, const ContactModelSpec& spec) {
  const ContactConstants& c = probe.constants;
  const ContactForces& law = *probe.law;
  const double adhesion_work = 2.0 * c.pull_off_force * c.critical_overlap;
  const double energy = 0.5 * c.mass * probe.speed * probe.speed + 2.0 * adhesion_work;
  Stiffest s;
  s.deepest = overlap_for_energy(law, c, std::max(energy, 1e-300));
  const double equilibrium =
      c.equilibrium_radius > 0.0 ? c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius) : 0.0;
  for (double overlap : {s.deepest, equilibrium})
    if (overlap > 0.0) {
      const double kn = normal_stiffness(law, c, overlap);
      const double a = law.normal_response(overlap, c).contact_radius;
      const double kt = spec.tangential ? 3.5 * 8.0 * c.shear * a : 0.0;
      // Rolling mode: torsional stiffness k_r R* over the relative moment of inertia, at least
      // (2/5) m* R*^2 (a sphere on a wall); as a translational stiffness, 2.5 k_r / R*.
      const double x = c.equilibrium_radius > 0.0 ? a / c.equilibrium_radius : 0.0;
      const double kr = spec.rolling ? 2.5 * 4.0 * c.pull_off_force * x * std::sqrt(x) / c.radius : 0.0;
      s.stiffness = std::max({s.stiffness, kn, kt, kr});
    }
  return s;
}

// The shortest contact period over the probes (infinite if none has a stiffness).
void shortest_period(const std::vector<Probe>& probes, const ContactModelSpec& spec, TimeStepEstimate& best) {
  best.period = std::numeric_limits<double>::infinity();
  for (const Probe& probe : probes) {
    const Stiffest s = stiffest_mode(probe, spec);
    if (s.stiffness <= 0.0) continue;
    const double period = 2.0 * std::numbers::pi * std::sqrt(probe.constants.mass / s.stiffness);
    if (period < best.period) {
      best.period = period;
      best.stiffness = s.stiffness;
      best.mass = probe.constants.mass;
      best.overlap = s.deepest;
    }
  }
}

// The shortest time in which a contact the run can make crosses its break overlap at its
// approach speed (0 if none has a tensile range or approaches).
void shortest_crossing(const std::vector<Probe>& probes, std::size_t particles, TimeStepEstimate& best) {
  best.crossing_time = std::numeric_limits<double>::infinity();
  for (const Probe& probe : probes) {
    const double range = probe.constants.break_overlap;
    if (!(range > 0.0) || !(probe.speed > 0.0) || (probe.between_particles && particles < 2)) continue;
    if (range / probe.speed < best.crossing_time) {
      best.crossing_time = range / probe.speed;
      best.break_overlap = range;
      best.approach_speed = probe.speed;
    }
  }
  if (!std::isfinite(best.crossing_time)) best.crossing_time = 0.0;
}

}  // namespace

BreakOverlaps shortest_break_overlaps(const Particles& p, const MaterialTable& materials,
                                      const std::vector<Wall>& walls, const ContactModelSpec& spec) {
  BreakOverlaps shortest;
  if (p.size() == 0) return shortest;
  const ProbeSet set = probes_of(p, materials, walls, spec, 0.0);
  for (const Probe& probe : set.probes) {
    const double range = probe.constants.break_overlap;
    if (!(range > 0.0) || (probe.between_particles && p.size() < 2)) continue;
    double& bound = probe.between_particles ? shortest.pair : shortest.wall;
    bound = bound > 0.0 ? std::min(bound, range) : range;
    const ContactConstants& c = probe.constants;
    double& speed = probe.between_particles ? shortest.pair_adhesion_speed : shortest.wall_adhesion_speed;
    speed = std::max(speed, std::sqrt(2.0 * c.pull_off_force * c.critical_overlap / c.mass));
  }
  return shortest;
}

const char* time_step_limit_name(TimeStepLimit limit) {
  return limit == TimeStepLimit::break_overlap ? "break_overlap" : "contact_period";
}

TimeStepEstimate recommend_time_step(const Particles& p, const MaterialTable& materials, const std::vector<Wall>& walls,
                                     const ContactModelSpec& spec, double max_speed, const TimeStepFactors& factors) {
  if (p.size() == 0) throw std::invalid_argument("time step: no particles");
  if (!(factors.steps_per_period >= 1.0)) throw std::invalid_argument("time step: steps_per_period must be >= 1");
  if (!(factors.steps_per_break_overlap >= 0.0))
    throw std::invalid_argument("time step: steps_per_break_overlap must be >= 0");

  const ProbeSet set = probes_of(p, materials, walls, spec, max_speed);
  TimeStepEstimate best;
  shortest_period(set.probes, spec, best);
  if (!std::isfinite(best.period)) throw std::invalid_argument("time step: no contact stiffness to set it by");
  shortest_crossing(set.probes, p.size(), best);
  best.steps_per_period = factors.steps_per_period;
  best.steps_per_break_overlap = factors.steps_per_break_overlap;
  best.time_step = best.period / factors.steps_per_period;
  if (factors.steps_per_break_overlap > 0.0 && best.crossing_time > 0.0 &&
      best.crossing_time / factors.steps_per_break_overlap < best.time_step) {
    best.time_step = best.crossing_time / factors.steps_per_break_overlap;
    best.limit = TimeStepLimit::break_overlap;
  }
  return best;
}

}  // namespace aerobreak
