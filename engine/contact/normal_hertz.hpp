#pragma once
#include <algorithm>
#include <cmath>

#include "engine/contact/contact_constants.hpp"
#include "engine/core/fast_math.hpp"

namespace aerobreak {

// Plain Hertz contact without adhesion: F = (4/3) E* sqrt(R*) delta^(3/2), a = sqrt(R* delta)
// (Hertz 1882; report eq 1 without its adhesive term, with delta = 4a^2/d for identical spheres).
struct HertzNormal {
  static constexpr bool adhesive = false;

  void complete(ContactConstants& c) const {
    c.hertz_coefficient = 4.0 / 3.0 * c.modulus * std::sqrt(c.radius);
    c.equilibrium_radius = 0.0;
    c.pull_off_force = 0.0;
    c.critical_overlap = 0.0;
    c.break_overlap = 0.0;
  }

  [[gnu::always_inline]] NormalResponse respond(double delta, const ContactConstants& c) const {
    const double overlap = positive_part(delta);
    NormalResponse r;
    r.force = c.hertz_coefficient * overlap * std::sqrt(overlap);
    r.contact_radius = std::sqrt(c.radius * overlap);
    r.coulomb_load = r.force;
    r.energy = 0.4 * r.force * overlap;
    return r;
  }
};

}  // namespace aerobreak
