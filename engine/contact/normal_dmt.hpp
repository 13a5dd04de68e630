#pragma once
#include <cmath>
#include <numbers>

#include "engine/contact/contact_constants.hpp"
#include "engine/core/fast_math.hpp"
#include "engine/contact/normal_hertz.hpp"

namespace aerobreak {

// Normal DMT law (Derjaguin, Muller & Toporov 1975; the report's alternative, section 2.1):
// Hertz repulsion plus a constant adhesive pull F_c = 2 pi w R* (= pi gamma d for identical
// spheres) while the spheres overlap. The contact ends when the overlap returns to zero.
struct DmtNormal {
  static constexpr bool adhesive = true;

  void complete(ContactConstants& c) const {
    HertzNormal{}.complete(c);
    c.pull_off_force = 2.0 * std::numbers::pi * c.work_of_adhesion * c.radius;
    // Radius at zero load, K delta0^(3/2) = F_c: the reference a0 of the rolling stiffness (eq 18).
    const double delta0 = std::cbrt(c.pull_off_force * c.pull_off_force / (c.hertz_coefficient * c.hertz_coefficient));
    c.equilibrium_radius = std::sqrt(c.radius * delta0);
  }

  [[gnu::always_inline]] NormalResponse respond(double delta, const ContactConstants& c) const {
    NormalResponse r = HertzNormal{}.respond(delta, c);
    r.coulomb_load = r.force;  // the Hertz part, F_n + F_c
    r.force -= c.pull_off_force;
    r.energy -= c.pull_off_force * positive_part(delta);
    const double x = r.contact_radius / c.equilibrium_radius;
    r.radius_ratio_three_halves = x * std::sqrt(x);
    return r;
  }
};

}  // namespace aerobreak
