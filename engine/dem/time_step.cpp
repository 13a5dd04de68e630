#include "engine/dem/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <limits>
#include <set>
#include <stdexcept>

namespace aerobreak {
namespace {

struct Probe {
  ContactConstants constants;
  double speed;
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

}  // namespace

TimeStepEstimate recommend_time_step(const Particles& p, const MaterialTable& materials, const std::vector<Wall>& walls,
                                     const ContactModelSpec& spec, double max_speed, double steps_per_period) {
  if (p.size() == 0) throw std::invalid_argument("time step: no particles");
  if (!(steps_per_period >= 1.0)) throw std::invalid_argument("time step: steps_per_period must be >= 1");

  // The extreme radii and masses over all particles, combined with every pair of materials present.
  std::set<std::uint16_t> present(p.material.begin(), p.material.end());
  std::vector<std::pair<double, double>> spheres;  // radius, mass
  for (std::size_t i = 0; i < p.size(); ++i) spheres.push_back({p.radius[i], p.mass[i]});
  const auto [small, large] = std::minmax_element(spheres.begin(), spheres.end());

  std::vector<Probe> probes;
  for (auto a : present)
    for (auto b : present)
      for (auto u : {small, large})
        for (auto v : {small, large}) {
          probes.push_back(
              {sphere_pair_constants(u->first, u->second, v->first, v->second, materials.pair(a, b)), 2.0 * max_speed});
        }
  const auto pair_law = make_contact_forces(spec, spec.normal);
  for (auto& probe : probes) pair_law->complete(probe.constants);

  std::vector<std::pair<Probe, const ContactForces*>> all;
  for (const auto& probe : probes) all.push_back({probe, pair_law.get()});
  std::vector<std::unique_ptr<ContactForces>> wall_laws;
  for (const Wall& wall : walls) {
    wall_laws.push_back(make_contact_forces(spec, wall.adhesive ? spec.normal : NormalLaw::hertz));
    for (auto a : present)
      for (auto u : {small, large}) {
        Probe probe{sphere_wall_constants(u->first, u->second, materials.pair(a, wall.material)), max_speed};
        wall_laws.back()->complete(probe.constants);
        all.push_back({probe, wall_laws.back().get()});
      }
  }

  TimeStepEstimate best;
  best.period = std::numeric_limits<double>::infinity();
  for (const auto& [probe, law] : all) {
    const ContactConstants& c = probe.constants;
    const double adhesion_work = 2.0 * c.pull_off_force * c.critical_overlap;
    const double energy = 0.5 * c.mass * probe.speed * probe.speed + 2.0 * adhesion_work;
    const double deepest = overlap_for_energy(*law, c, std::max(energy, 1e-300));
    const double equilibrium = c.equilibrium_radius > 0.0 ? c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius) : 0.0;
    double stiffness = 0.0;
    for (double overlap : {deepest, equilibrium})
      if (overlap > 0.0) {
        const double kn = normal_stiffness(*law, c, overlap);
        const double a = law->normal_response(overlap, c).contact_radius;
        const double kt = spec.tangential ? 3.5 * 8.0 * c.shear * a : 0.0;
        // Rolling mode: torsional stiffness k_r R* over the relative moment of inertia, at least
        // (2/5) m* R*^2 (a sphere on a wall); as a translational stiffness, 2.5 k_r / R*.
        const double x = c.equilibrium_radius > 0.0 ? a / c.equilibrium_radius : 0.0;
        const double kr = spec.rolling ? 2.5 * 4.0 * c.pull_off_force * x * std::sqrt(x) / c.radius : 0.0;
        stiffness = std::max({stiffness, kn, kt, kr});
      }
    if (stiffness <= 0.0) continue;
    const double period = 2.0 * std::numbers::pi * std::sqrt(c.mass / stiffness);
    if (period < best.period) {
      best.period = period;
      best.stiffness = stiffness;
      best.mass = c.mass;
      best.overlap = deepest;
    }
  }
  if (!std::isfinite(best.period)) throw std::invalid_argument("time step: no contact stiffness to set it by");
  best.steps_per_period = steps_per_period;
  best.time_step = best.period / steps_per_period;
  return best;
}

}  // namespace aerobreak
