#include "engine/impact/contact_scales.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace aerobreak {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Contact radius over R* at `overlap_ratio` (overlap over R*) for the completed constants `c`.
double contact_radius_over_reduced(const ContactForces& law, const ContactConstants& c, double overlap_ratio) {
  return law.normal_response(overlap_ratio * c.radius, c).contact_radius / c.radius;
}

}  // namespace

ContactEnergies contact_energies(const ContactForces& law, ContactConstants c, double critical_rolling) {
  law.complete(c);
  ContactEnergies e;
  e.pull_off_force = c.pull_off_force;
  e.critical_overlap = c.critical_overlap;
  e.break_overlap = c.break_overlap;
  e.equilibrium_overlap = zero_load_overlap(law, c);
  e.breaking_energy =
      law.normal_response(-c.break_overlap, c).energy - law.normal_response(e.equilibrium_overlap, c).energy;
  // 6 pi^2 gamma R* xi_crit with gamma = w/2.
  e.rolling_energy = critical_rolling > 0.0
                         ? 3.0 * std::numbers::pi * std::numbers::pi * c.work_of_adhesion * c.radius * critical_rolling
                         : kNaN;
  return e;
}

EnergyGroups energy_groups(double impact_kinetic_energy, std::size_t initial_contacts,
                           const ContactEnergies& energies) {
  EnergyGroups g;
  g.energy_per_contact =
      initial_contacts > 0 && energies.breaking_energy > 0.0
          ? impact_kinetic_energy / (static_cast<double>(initial_contacts) * energies.breaking_energy)
          : kNaN;
  g.energy_over_rolling = energies.rolling_energy > 0.0 ? impact_kinetic_energy / energies.rolling_energy : kNaN;
  return g;
}

SmallStrainCheck check_small_strain(const DeepestOverlaps& deepest, const Particles& particles,
                                    const MaterialTable& materials, const Wall& wall, const ContactModelSpec& spec,
                                    const StrainLimits& limits) {
  SmallStrainCheck check;
  check.limits = limits;
  if (particles.size() == 0) return check;
  const auto [smallest, largest] = std::minmax_element(particles.radius.begin(), particles.radius.end());
  const auto i = static_cast<std::size_t>(smallest - particles.radius.begin());
  const double r = *smallest, m = particles.mass[i];
  const std::uint16_t material = particles.material[i];
  check.bound = *largest != r;
  if (deepest.pair) {
    // The contact radius over R* grows with a0/R*, which is largest for the smallest R* (two
    // smallest primaries); R*/R of the smaller primary is largest for the most unequal pair,
    // R_max/(R_min + R_max), 1/2 for equal primaries.
    const auto law = make_contact_forces(spec, spec.normal);
    ContactConstants c = sphere_pair_constants(r, m, r, m, materials.pair(material, material));
    law->complete(c);
    const double share = *largest / (r + *largest);
    check.pair.overlap_ratio = *deepest.pair * share;
    check.pair.contact_radius_ratio = contact_radius_over_reduced(*law, c, *deepest.pair) * share;
  }
  if (deepest.wall) {
    // R* is the primary's radius; the contact radius over it grows with a0/R, largest for the
    // smallest primary.
    const auto law = make_contact_forces(spec, wall.adhesive ? spec.normal : NormalLaw::hertz);
    ContactConstants c = sphere_wall_constants(r, m, materials.pair(material, wall.material));
    law->complete(c);
    check.wall.overlap_ratio = *deepest.wall;
    check.wall.contact_radius_ratio = contact_radius_over_reduced(*law, c, *deepest.wall);
  }
  check.worst.overlap_ratio = std::max(check.pair.overlap_ratio, check.wall.overlap_ratio);
  check.worst.contact_radius_ratio = std::max(check.pair.contact_radius_ratio, check.wall.contact_radius_ratio);
  check.within = check.worst.overlap_ratio <= limits.overlap_ratio &&
                 check.worst.contact_radius_ratio <= limits.contact_radius_ratio;
  return check;
}

}  // namespace aerobreak
