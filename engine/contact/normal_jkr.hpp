#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/contact/contact_constants.hpp"
#include "engine/core/fast_math.hpp"

namespace aerobreak {

// Where a JKR contact in tension lets go (docs/MODEL.md 3.3).
enum class JkrSeparation {
  displacement,  // at delta = -delta_c (eq 3), the report's rule and the default
  force,         // at a = a0 / 4^(1/3), where F = -F_c: the rule of some DEM codes
};

// Contact radius ratio x = a/a0 on the stable JKR branch for the overlap ratio D = delta R*/a0^2.
// Eq 2 in these variables reads y^4 - (2/3) y - D = 0 with y = sqrt(x). Adding 2 m y^2 + m^2 to
// both sides makes the right side a perfect square when m solves the resolvent cubic
// m^3 + D m - 1/18 = 0; then y = [sqrt(2m) + sqrt(2 sqrt(2) / (3 sqrt(m)) - 2m)] / 2.
// The cubic has one real root for D > -1/(2 6^(1/3)) (= -delta_c R*/a0^2); Cardano's form is
// rearranged as m = (u^3 - v^3) / (u^2 + u v + v^2) = 1 / (18 q), q = u^2 + u v + v^2, with
// u = (1/36 + s)^(1/3), v = D / (3u), s = sqrt(1/1296 + D^3/27): no cancellation for any D.
// With w = sqrt(18 q) = 1/sqrt(m): y = [sqrt(2)/w + sqrt((2 sqrt(2)/3) w - 2/w^2)] / 2.
// Closed form: three square roots and one division (the cube root is an inlined elementary
// function); no iteration on eq 2 in the pair loop.
// Returns y = sqrt(a/a0); jkr_radius_ratio gives x = a/a0 = y^2.
[[gnu::always_inline]] inline double jkr_root_radius_ratio(double overlap_ratio) {
  const double d = overlap_ratio;
  const double s = std::sqrt(positive_part(1.0 / 1296.0 + d * d * d / 27.0));
  const double t = 1.0 / 36.0 + s;
  const double inverse_u = inverse_cube_root(t);
  const double u = t * inverse_u * inverse_u;
  const double v = d * inverse_u * (1.0 / 3.0);
  const double w = std::sqrt(18.0 * (u * u + u * v + v * v));
  const double inverse_w = 1.0 / w;
  const double inner = positive_part(2.0 * std::numbers::sqrt2 / 3.0 * w - 2.0 * inverse_w * inverse_w);
  return 0.5 * (std::numbers::sqrt2 * inverse_w + std::sqrt(inner));
}

inline double jkr_radius_ratio(double overlap_ratio) {
  const double y = jkr_root_radius_ratio(overlap_ratio);
  return y * y;
}

// Overlap ratio delta R*/a0^2 of the radius ratio x (eq 2 with eq 3 inserted).
inline double jkr_overlap_ratio(double x) { return x * x - (2.0 / 3.0) * std::sqrt(x); }

// Normal JKR law (Johnson, Kendall & Roberts 1971; report eqs 1-5) in the general form of
// docs/MODEL.md section 2 (eqs 1-2, general form): F(a) = 4E*a^3/(3R*) - sqrt(8 pi w E* a^3), delta(a) = a^2/R* -
// sqrt(2 pi w a/E*).
struct JkrNormal {
  JkrSeparation separation = JkrSeparation::displacement;

  static constexpr bool adhesive = true;

  void complete(ContactConstants& c) const {
    c.hertz_coefficient = 4.0 / 3.0 * c.modulus * std::sqrt(c.radius);
    // eq 4: a0 = (9 pi w R*^2 / (2 E*))^(1/3)
    c.equilibrium_radius =
        std::cbrt(9.0 * std::numbers::pi * c.work_of_adhesion * c.radius * c.radius / (2.0 * c.modulus));
    // eq 5: F_c = 1.5 pi w R* (= 3 pi gamma d / 4 for identical spheres)
    c.pull_off_force = 1.5 * std::numbers::pi * c.work_of_adhesion * c.radius;
    const double a0_squared_over_r = c.equilibrium_radius * c.equilibrium_radius / c.radius;
    // eq 3: delta_c = a0^2 / (2 6^(1/3) R*) (= 2 a0^2 / (d 6^(1/3)) for identical spheres)
    c.critical_overlap = a0_squared_over_r / (2.0 * std::cbrt(6.0));
    c.break_overlap = separation == JkrSeparation::displacement
                          ? c.critical_overlap
                          : -a0_squared_over_r * jkr_overlap_ratio(std::pow(4.0, -1.0 / 3.0));
    c.overlap_scale = 1.0 / a0_squared_over_r;
  }

  // Eq 2 solved in closed form for y = sqrt(a/a0), then eqs 1 and 5.
  [[gnu::always_inline]] NormalResponse respond(double delta, const ContactConstants& c) const {
    const double y = jkr_root_radius_ratio(delta * c.overlap_scale);
    const double a0 = c.equilibrium_radius;
    const double x = y * y;
    const double x_three_halves = x * y;
    NormalResponse r;
    // eq 5: F / F_c = 4 [(a/a0)^3 - (a/a0)^(3/2)]
    r.force = 4.0 * c.pull_off_force * (x * x * x - x_three_halves);
    r.contact_radius = a0 * x;
    r.radius_ratio_three_halves = x_three_halves;
    // eq 14: the friction limit is mu (F_n + 2 F_c)
    r.coulomb_load = positive_part(r.force + 2.0 * c.pull_off_force);
    r.energy = 4.0 * c.pull_off_force * a0 * a0 / c.radius * (energy_primitive(x, y) - kTouchPrimitive);
    return r;
  }

  // Work done against F along eq 2, from touching (delta = 0) to the radius ratio x = y^2:
  // U = integral F d(delta) = 4 F_c a0^2/R* [P(x) - P(x_touch)], P = (2/5)x^5 - (2/3)x^(7/2) + x^2/6.
  static double energy_primitive(double x, double y) {
    return 0.4 * x * x * x * x * x - (2.0 / 3.0) * x * x * x * y + x * x / 6.0;
  }
  // a/a0 at delta = 0 solves x^(3/2) = 2/3, so x^3 = 4/9 and P there is
  // x^2 [(2/5)(4/9) - (2/3)(2/3) + 1/6] = -(1/10) x^2.
  static constexpr double kTouchRatioSquared = 0.582386976490865913;  // (4/9)^(2/3)
  static constexpr double kTouchPrimitive = -0.1 * kTouchRatioSquared;
};

}  // namespace aerobreak
