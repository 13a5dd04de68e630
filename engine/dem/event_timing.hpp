#pragma once
#include <algorithm>
#include <cmath>

namespace aerobreak {

// Contact events at the time they happen within a step (docs/MODEL.md 9.2).
//
// Velocity Verlet applies the force found at step n+1 as an impulse dt F(n+1), half in the
// closing kick of step n+1 and half in the opening kick of the next: as if it had acted from the
// half step n+1/2 on. Where a contact forms or lets go its normal force jumps (JKR, eqs 1-5:
// from 0 to -(8/9) F_c at touching; from -(5/9) F_c at -delta_c, or -F_c by the force rule, to
// 0), and the overlap crossed its threshold at a time t* = t(n) + s dt within the drift from
// step n to step n+1, not at n+1/2. Left alone, the jump acts (1/2 - s) dt too long or too short,
// and the energy one contact cycle loses (the JKR hysteresis) is off by up to |jump| v dt / 2 at
// each event: first order in v dt / delta_b.

// Fraction s in [0, 1] of the drift at which the overlap, moving linearly from `before` (step n)
// to `after` (step n+1) as velocity Verlet's drift moves it, crossed `threshold`.
inline double crossing_fraction(double before, double after, double threshold) {
  const double span = after - before;
  if (!(span != 0.0)) return 1.0;
  return std::clamp((threshold - before) / span, 0.0, 1.0);
}

// Normal force (> 0 pushing apart) to add at step n+1 for a force that jumped by `jump` (after
// minus before) at the fraction s of the drift: its two half kicks add jump (1/2 - s) dt, so that
// the jump's impulse is jump (t(n+3/2) - t*), the exact one for a force constant near t*.
inline double jump_timing_force(double jump, double fraction) { return jump * (0.5 - fraction); }

// The second-order part, where a contact forms: the drift that made it moved the bodies as if the
// jump had not yet acted, so at step n+1 their relative position lags the true one by
// jump dt^2 (1 - s)^2 / (2 m*) along the normal, and the pair stands in the jump's field with an
// excess energy jump^2 dt^2 (1 - s)^2 / (2 m*) (the same sign for either sign of the jump).
// An impulse against the approach, of that energy over the approach rate u = travel / dt,
// removes it: the normal force jump^2 dt (1 - s)^2 / (2 m* u). Where the approach is too slow for
// a step to resolve (the force would change u by more than u itself), it is capped at |jump| / 2.
// (At separation the bodies fly apart free, and a lag of position costs no energy.)
inline double formation_lag_force(double jump, double fraction, double travel, double reduced_mass, double dt) {
  if (!(travel > 0.0) || !(dt > 0.0)) return 0.0;
  const double approach_rate = travel / dt;
  const double late = 1.0 - fraction;
  const double force = jump * jump * dt * late * late / (2.0 * reduced_mass * approach_rate);
  return std::min(force, 0.5 * std::fabs(jump));
}

}  // namespace aerobreak
