#pragma once
#include <algorithm>

#include "engine/contact/contact_state.hpp"
#include "engine/contact/dissipation.hpp"
#include "engine/contact/rolling_resistance.hpp"
#include "engine/contact/tangential_mindlin.hpp"

namespace aerobreak {

// Relative motion of the two bodies at a contact. For a wall, j's velocities are zero.
struct ContactMotion {
  Vec3 normal;           // unit vector from i towards j (into the wall for a wall contact)
  double overlap = 0.0;  // delta = Ri + Rj - r (> 0 when pressed together)
  Vec3 velocity;         // v_i - v_j
  Vec3 spin_i;           // w_i
  Vec3 spin_j;           // w_j
  // Distances from the centres to the contact point. They add up to the centre distance
  // (R_i - delta/2 and R_j - delta/2; R_i - delta for a wall), so that the tangential force
  // exerts no net torque on the pair and angular momentum is conserved.
  double lever_i = 0.0;
  double lever_j = 0.0;
};

struct ContactLoad {
  Vec3 force_i;  // force on i; j receives -force_i
  Vec3 torque_i;
  Vec3 torque_j;
};

// One contact law assembled from its slots (docs/ARCHITECTURE.md, "The engine"); the combination is a type, chosen
// once per run, so the pair loop holds no model switches.
template <class Normal, class Damping, class Tangential, class Rolling, class Twisting>
struct ContactModel {
  Normal normal;
  Damping damping;
  Tangential tangential;
  Rolling rolling;
  Twisting twisting;

  // Fills the adhesion constants of a contact that has just formed at radius a(overlap).
  void open(ContactState& s, double overlap) const {
    normal.complete(s.constants);
    s.contact_radius = normal.respond(overlap, s.constants).contact_radius;
    s.overlap = overlap;
  }

  // Elastic energy of all the contact's springs at its last evaluation.
  double stored_energy(const ContactHistory& s, const ContactConstants& c) const {
    return stored_energy(s, c, normal.respond(s.overlap, c));
  }
  // The same, given the normal law's response at the last evaluation's overlap.
  double stored_energy(const ContactHistory& s, const ContactConstants& c, const NormalResponse& last) const {
    return last.energy + tangential.energy(s.tangential_stretch, s.contact_radius, c) +
           rolling.energy(s.rolling_displacement, s.contact_radius, c) +
           twisting.energy(s.twist_angle, s.contact_radius, c);
  }

  // Energy a contact takes with it when it lets go, found at `overlap` after the step: the work
  // of its normal force is booked only where that force acts, from the last evaluation down to
  // where the law lets go, max(overlap, -delta_b) (exactly, as the change of U_n; a Hertz or DMT
  // contact lets go at delta = 0, where U_n = 0), so that it takes U_n there; with it what the
  // other springs stored at the last evaluation; and the last damping force's work over its final
  // half step. (The integrator's own error over the final step stays in the balance, as for any
  // other step: docs/MODEL.md 10.)
  void release(const ContactState& s, double overlap, double approach_rate, double dt, DissipationTally& tally) const {
    const NormalResponse last = normal.respond(s.overlap, s.constants);
    const double other_springs = stored_energy(s, s.constants, last) - last.energy;
    const double let_go = std::max(overlap, -s.constants.break_overlap);
    tally.breaking += normal.respond(let_go, s.constants).energy + other_springs;
    tally.damping += 0.5 * s.damping_force * approach_rate * dt;
  }

  // Forces and torques of a live contact (eq 15 and eq 16), updating its history.
  [[gnu::always_inline]] ContactLoad evaluate(ContactState& s, const ContactMotion& m, double dt,
                                              DissipationTally& tally) const {
    return evaluate(s, s.constants, m, dt, tally);
  }

  // The same for a history and constants kept apart (the pair loop reads them from the pool's
  // columns). Straight-line code with selects for the laws' limits, so that a loop over
  // contacts vectorises.
  [[gnu::always_inline]] ContactLoad evaluate(ContactHistory& s, const ContactConstants& c, const ContactMotion& m,
                                              double dt, DissipationTally& tally) const {
    const NormalResponse response = normal.respond(m.overlap, c);
    const Vec3 contact_velocity = m.velocity + cross(m.lever_i * m.spin_i + m.lever_j * m.spin_j, m.normal);
    const double approach_rate = dot(contact_velocity, m.normal);
    const double damping_force = damping.coefficient(response, c) * approach_rate;
    // Work of the damping force over the last step, trapezoidal in the force as velocity Verlet
    // applies it: the previous force acted from v(n-1/2) to v(n+1/2), this one from v(n+1/2) on.
    tally.damping += 0.5 * (s.damping_force + damping_force) * approach_rate * dt;
    s.damping_force = damping_force;
    // eq 12: elastic (eq 5) plus viscous normal force, > 0 pushing the bodies apart
    const double normal_force = response.force + damping_force;

    const SpringContext spring{m.normal,
                               dt,
                               response.contact_radius,
                               s.contact_radius,
                               response.coulomb_load,
                               response.radius_ratio_three_halves};
    const Vec3 slip_velocity = contact_velocity - approach_rate * m.normal;
    const Vec3 tangential_force = tangential.force(s.tangential_stretch, slip_velocity, spring, c, tally);
    const Vec3 relative_spin = m.spin_i - m.spin_j;
    const Vec3 resistance = rolling.torque(s.rolling_displacement, relative_spin, spring, c, tally) +
                            twisting.torque(s.twist_angle, relative_spin, spring, c, tally);
    s.contact_radius = response.contact_radius;
    s.overlap = m.overlap;

    const Vec3 lever_torque = cross(m.normal, tangential_force);
    return {tangential_force - normal_force * m.normal, m.lever_i * lever_torque + resistance,
            m.lever_j * lever_torque - resistance};
  }
};

}  // namespace aerobreak
