#pragma once
#include <cmath>

#include "engine/contact/contact_constants.hpp"
#include "engine/contact/dissipation.hpp"
#include "engine/contact/spring.hpp"

namespace aerobreak {

// What a tangential, rolling or twisting law reads of the current contact.
struct SpringContext {
  Vec3 normal;  // unit normal, from i to j
  double dt = 0.0;
  double contact_radius = 0.0;             // a, this step
  double previous_radius = 0.0;            // a, last step (for the stiffness change)
  double coulomb_load = 0.0;               // from the normal law: F_n + 2 F_c for JKR (eq 14)
  double radius_ratio_three_halves = 0.0;  // (a/a0)^(3/2), from the normal law
};

struct NoTangential {
  Vec3 force(Vec3&, const Vec3&, const SpringContext&, const ContactConstants&, DissipationTally&) const { return {}; }
  static double energy(const Vec3&, double, const ContactConstants&) { return 0.0; }
};

// Mindlin no-slip spring with Coulomb slip (report eqs 10-14). k_t = 8 G* a, which is eq 11,
// k_t = 2G/(2-nu) sqrt(d delta), for identical spheres with a = sqrt(R* delta). The spring
// stretch is the contact history; |F_t| <= mu (F_n + 2 F_c) (eq 14). Tangential damping: none
// (as in the report).
struct MindlinTangential {
  double friction = 0.0;  // mu

  // stretch: the history; slip_velocity: tangential velocity of i's contact point relative to j's.
  // Returns the tangential force on i.
  [[gnu::always_inline]] Vec3 force(Vec3& stretch, const Vec3& slip_velocity, const SpringContext& s,
                                    const ContactConstants& c, DissipationTally& tally) const {
    stretch = rotate_into_plane(stretch, s.normal);
    const double stiffness = stiffness_at(s.contact_radius, c);
    // 0.5 (k_t - k_t,previous) |s|^2, with the difference taken of the radii: exactly zero at a
    // constant radius, however the compiler fuses the multiplications.
    tally.stiffness_work += 4.0 * c.shear * (s.contact_radius - s.previous_radius) * norm2(stretch);
    const Vec3 before = stretch;
    const Vec3 increment = slip_velocity * s.dt;
    stretch += increment;
    const double limit = friction * s.coulomb_load;
    const double trial2 = stiffness * stiffness * norm2(stretch);
    // Selects, not branches, so that the pair loop vectorises: a spring that slides is cut back
    // to the Coulomb limit and books what it dissipated; one that sticks is left exactly as is.
    const bool slides = trial2 > limit * limit;
    stretch *= slides ? limit / std::sqrt(trial2) : 1.0;
    tally.friction += slides ? slip_dissipation(stiffness, before, increment, stretch) : 0.0;
    return -stiffness * stretch;
  }

  // k_t = 8 G* a at contact radius a.
  static double stiffness_at(double contact_radius, const ContactConstants& c) {
    return 8.0 * c.shear * contact_radius;
  }

  // Energy of the spring stretched by `stretch` at contact radius a: k_t |s|^2 / 2.
  static double energy(const Vec3& stretch, double contact_radius, const ContactConstants& c) {
    return 0.5 * stiffness_at(contact_radius, c) * norm2(stretch);
  }
};

}  // namespace aerobreak
