#pragma once
#include <cmath>
#include <numbers>

#include "engine/contact/contact_constants.hpp"

namespace aerobreak {

// Normal damping laws: each returns the coefficient eta of the force eta * d(delta)/dt that is
// added to the elastic normal force.

struct NoDamping {
  double coefficient(const NormalResponse&, const ContactConstants&) const { return 0.0; }
};

// Visco-elastic damping (Brilliantov et al. 1996; report eq 8): F = (3/2) A K sqrt(delta) d(delta)/dt
// for a Hertz contact, i.e. eta = 2 A E* a with a = sqrt(R* delta). For adhesive contacts the
// contact radius a of the normal law is used, so the damping acts in tension as well.
// A (a time) is the material's dissipative constant, set by its bulk and shear viscosities.
struct ViscoElasticDamping {
  double dissipative_time = 0.0;  // A

  [[gnu::always_inline]] double coefficient(const NormalResponse& n, const ContactConstants& c) const {
    return 2.0 * dissipative_time * c.modulus * n.contact_radius;
  }
};

// Tsuji damping (Tsuji, Tanaka & Ishida 1992; report eq 9): eta = alpha sqrt(m* K) delta^(1/4),
// K = (4/3) E* sqrt(R*). delta^(1/4) is taken at the Hertz overlap a^2/R* of the current contact
// radius, so that it stays defined in tension for adhesive contacts.
struct TsujiDamping {
  double alpha = 0.0;

  [[gnu::always_inline]] double coefficient(const NormalResponse& n, const ContactConstants& c) const {
    const double hertz_overlap = n.contact_radius * n.contact_radius / c.radius;
    return alpha * std::sqrt(c.mass * c.hertz_coefficient * std::sqrt(hertz_overlap));
  }
};

// alpha for a target coefficient of restitution e of a Hertz contact with Tsuji damping:
// alpha = sqrt(5) |ln e| / sqrt(ln^2 e + pi^2). Exact for Hertz: with d(tau) = delta^(1/4) dt the
// Hertz-Tsuji impact becomes a linear damped oscillator in delta^(5/4), whose restitution is
// exp(-pi beta / sqrt(1 - beta^2)); hence e is also independent of the impact speed.
inline double tsuji_alpha(double restitution) {
  const double log_e = std::log(restitution);
  return std::sqrt(5.0) * -log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
}

// The inverse of tsuji_alpha: e = exp(-alpha pi / sqrt(5 - alpha^2)), for 0 <= alpha < sqrt(5).
inline double tsuji_restitution(double alpha) {
  return std::exp(-alpha * std::numbers::pi / std::sqrt(5.0 - alpha * alpha));
}

// alpha that makes Tsuji damping the share `ratio` of the critical damping 2 sqrt(k m*) of a JKR
// contact about its equilibrium a = a0, for every R*, m* and E* alike. There eq 9 at the Hertz
// overlap a0^2/R* gives eta = alpha sqrt((4/3) E* a0 m*), and the stiffness is
// k = dF/d(delta) = 3.6 F_c R*/a0^2 = 1.2 E* a0 (eqs 2, 4, 5), so eta / (2 sqrt(k m*)) = alpha / sqrt(3.6).
// (Visco-elastic damping, eta = 2 A E* a, has no such constant share: with one A it grows
// relative to critical as R*^(-7/6).)
inline double tsuji_alpha_for_jkr_damping_ratio(double ratio) { return std::sqrt(3.6) * ratio; }

}  // namespace aerobreak
