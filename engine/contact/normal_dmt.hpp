#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/contact/contact_constants.hpp"

namespace aerobreak {

// Normal DMT law (Derjaguin, Muller & Toporov 1975; the report's alternative, section 2.1):
// Hertz repulsion plus a constant adhesive pull F_c = 2 pi w R* (= pi gamma d for identical
// spheres) while the spheres overlap. The contact ends when the overlap returns to zero.
struct DmtNormal {
  static constexpr bool adhesive = true;

  void complete(ContactConstants& c) const {
    c.hertz_coefficient = 4.0 / 3.0 * c.modulus * std::sqrt(c.radius);
    c.pull_off_force = 2.0 * std::numbers::pi * c.work_of_adhesion * c.radius;
    // Radius at zero load, K delta0^(3/2) = F_c: the reference a0 of the rolling stiffness (eq 18).
    const double delta0 = std::cbrt(c.pull_off_force * c.pull_off_force / (c.hertz_coefficient * c.hertz_coefficient));
    c.equilibrium_radius = std::sqrt(c.radius * delta0);
    c.critical_overlap = 0.0;
    c.break_overlap = 0.0;
  }

  static double solve(double delta) { return delta; }
  NormalResponse respond(double delta, const ContactConstants& c) const { return respond_solved(delta, c); }

  NormalResponse respond_solved(double delta, const ContactConstants& c) const {
    const double overlap = std::max(0.0, delta);
    const double root = std::sqrt(overlap);
    const double hertz = c.hertz_coefficient * overlap * root;
    NormalResponse r;
    r.force = hertz - c.pull_off_force;
    r.contact_radius = std::sqrt(c.radius * overlap);
    r.coulomb_load = hertz;
    r.energy = 0.4 * hertz * overlap - c.pull_off_force * overlap;
    const double x = r.contact_radius / c.equilibrium_radius;
    r.radius_ratio_three_halves = x * std::sqrt(x);
    return r;
  }
};

}  // namespace aerobreak
