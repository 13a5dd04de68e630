#pragma once
#include <cmath>

#include "engine/contact/tangential_mindlin.hpp"

namespace aerobreak {

struct NoRolling {
  Vec3 torque(Vec3&, const Vec3&, const SpringContext&, const ContactConstants&, DissipationTally&) const { return {}; }
  static double energy(const Vec3&, double, const ContactConstants&) { return 0.0; }
};

// Rolling resistance of sintered contacts (report section 2.2, eq 18, after Zhao & Marshall 2008
// and Marshall 2009): rolling displacement xi accumulated from the rolling velocity
// v_L = -R* (w_i - w_j) x n, rolling stiffness k_r = 4 F_c (a/a0)^(3/2), torque on i
// M = k_r n x xi with |M| <= k_r xi_crit: xi is held at length xi_crit while the contact rolls on.
// The spring energy is k_r |xi|^2 / (2 R*), so that M does the work of the spring exactly.
// Without adhesion (F_c = 0) k_r = 0 and the law exerts nothing. k_r follows from the contact
// radius, this step's and the last step's (SpringContext): the contact keeps no stiffness of its own.
struct RollingResistance {
  double critical_displacement = 0.0;  // xi_crit

  [[gnu::always_inline]] Vec3 torque(Vec3& displacement, const Vec3& relative_spin, const SpringContext& s,
                                     const ContactConstants& c, DissipationTally& tally) const {
    displacement = rotate_into_plane(displacement, s.normal);
    const double stiffness = 4.0 * c.pull_off_force * s.radius_ratio_three_halves;
    const double previous_stiffness = rolling_stiffness(s.previous_radius, c);
    const double compliance = energy_compliance(c);
    tally.stiffness_work += compliance * (stiffness - previous_stiffness) * norm2(displacement);
    const Vec3 before = displacement;
    const Vec3 increment = -c.radius * cross(relative_spin, s.normal) * s.dt;
    displacement += increment;
    const double length2 = norm2(displacement);
    const bool slips = length2 > critical_displacement * critical_displacement;  // selects: see Mindlin
    displacement *= slips ? critical_displacement / std::sqrt(length2) : 1.0;
    tally.rolling += slips ? slip_dissipation(2.0 * compliance * stiffness, before, increment, displacement) : 0.0;
    return stiffness * cross(s.normal, displacement);
  }

  // 1 / (2 R*): the spring's energy is k_r |xi|^2 times this.
  static double energy_compliance(const ContactConstants& c) { return 0.5 / c.radius; }

  // Energy of the spring displaced by xi at contact radius a: k_r |xi|^2 / (2 R*).
  static double energy(const Vec3& displacement, double contact_radius, const ContactConstants& c) {
    return energy_compliance(c) * rolling_stiffness(contact_radius, c) * norm2(displacement);
  }

  // k_r = 4 F_c (a/a0)^(3/2) (eq 18); 0 without adhesion, where a0 = 0 too.
  static double rolling_stiffness(double a, const ContactConstants& c) {
    const double x = c.pull_off_force > 0.0 ? a / c.equilibrium_radius : 0.0;
    return 4.0 * c.pull_off_force * x * std::sqrt(x);
  }
};

}  // namespace aerobreak
