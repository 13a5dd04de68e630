#pragma once
#include <cmath>

#include "engine/contact/spring.hpp"
#include "engine/contact/tangential_mindlin.hpp"

namespace aerobreak {

struct NoTwisting {
  Vec3 torque(double&, const Vec3&, const SpringContext&, const ContactConstants&, DissipationTally&) const {
    return {};
  }
  static double energy(double, double, const ContactConstants&) { return 0.0; }
};

// Twisting resistance (report section 2.2, eq 17, after Marshall 2009): a torsion spring on the
// relative twist angle phi about the normal, with stiffness k_tw = k_t a^2 / 2 = 4 G* a^3 (the
// Mindlin stiffness k_t = 8 G* a spread over the contact disk, whose polar second moment per unit
// area is a^2/2), and the slip limit |M_t| <= (2/3) mu a (F_n + 2 F_c) of eq 17.
struct TwistingResistance {
  double friction = 0.0;  // mu

  [[gnu::always_inline]] Vec3 torque(double& angle, const Vec3& relative_spin, const SpringContext& s,
                                     const ContactConstants& c, DissipationTally& tally) const {
    const double a = s.contact_radius;
    const double stiffness = stiffness_at(a, c);
    const double a_prev = s.previous_radius;
    // 0.5 (k_tw - k_tw,previous) phi^2 with a^3 - a_prev^3 factored: exactly zero at a constant radius.
    tally.stiffness_work += 2.0 * c.shear * (a - a_prev) * (a * a + a * a_prev + a_prev * a_prev) * angle * angle;
    const double before = angle;
    const double increment = dot(relative_spin, s.normal) * s.dt;
    angle += increment;
    const double limit = 2.0 / 3.0 * friction * a * s.coulomb_load;
    const double trial = stiffness * std::fabs(angle);
    const bool slips = trial > limit;  // selects: see Mindlin
    angle = slips ? (trial > 0.0 ? std::copysign(limit / stiffness, angle) : 0.0) : angle;
    tally.twisting +=
        slips ? slip_dissipation(stiffness, {before, 0.0, 0.0}, {increment, 0.0, 0.0}, {angle, 0.0, 0.0}) : 0.0;
    return -stiffness * angle * s.normal;
  }

  // k_tw = 4 G* a^3 at contact radius a.
  static double stiffness_at(double a, const ContactConstants& c) { return 4.0 * c.shear * a * a * a; }

  // Energy of the torsion spring twisted by phi at contact radius a: k_tw phi^2 / 2.
  static double energy(double angle, double contact_radius, const ContactConstants& c) {
    return 0.5 * stiffness_at(contact_radius, c) * angle * angle;
  }
};

}  // namespace aerobreak
