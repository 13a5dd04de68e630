#pragma once
// One JKR contact cycle (report eqs 1-5) without damping or friction: a sphere on an adhesive
// wall of its own material and two free spheres, the exact energy one approach-separation cycle
// dissipates in closed form and by quadrature, the sticking speed and restitution it gives, and a
// collision run by the engine. Shared by tests/engine/jkr_restitution_test.cpp and
// tests/bench/restitution_bench.cpp.
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/dem/simulation.hpp"
#include "support.hpp"

namespace aerobreak::testing::jkr_cycle {

inline constexpr double kGamma = 0.01;  // gamma / k_n
inline const double pi = std::numbers::pi;

// One contact's effective quantities (docs/MODEL.md 2) and the bodies it joins.
struct Contact {
  double modulus, work, radius, mass;  // E*, w, R*, m*
  bool with_wall;
};

inline Contact sphere_on_wall() {
  const Material m = testing::unit_material(kGamma);
  const PairMaterial pm = combine(m, m);
  return {pm.modulus, pm.work_of_adhesion, 0.5, 1.0, true};
}

inline Contact two_spheres() {
  Contact c = sphere_on_wall();
  c.radius = 0.25;
  c.mass = 0.5;
  c.with_wall = false;
  return c;
}

inline double equilibrium_radius(const Contact& c) {  // eq 4: a0 = (9 pi w R*^2 / (2 E*))^(1/3)
  return std::cbrt(9.0 * pi * c.work * c.radius * c.radius / (2.0 * c.modulus));
}

inline double pull_off_force(const Contact& c) { return 1.5 * pi * c.work * c.radius; }  // eq 5

inline double critical_overlap(const Contact& c) {  // eq 3: delta_c = a0^2 / (2 6^(1/3) R*)
  const double a0 = equilibrium_radius(c);
  return a0 * a0 / (2.0 * std::cbrt(6.0) * c.radius);
}

// The energy one cycle dissipates, in closed form: the contact forms at delta = 0 with no stored
// energy and lets go at the release radius a_r with U = W, the work of eq 1 along eq 2. In
// x = a/a0, with eqs 4 and 5, F = 4 F_c (x^3 - x^(3/2)) and delta = (a0^2/R*)(x^2 - (2/3) x^(1/2)),
// so F d(delta) = 4 F_c (a0^2/R*) (2x^4 - (7/3) x^(5/2) + x/3) dx = 4 F_c (a0^2/R*) dP with
// P(x) = (2/5) x^5 - (2/3) x^(7/2) + x^2/6 = x^2 [(2/5) x^3 - (2/3) x^(3/2) + 1/6].
// Touching: x^(3/2) = 2/3, P = -x^2/10. Release by displacement (d delta/da = 0, delta = -delta_c):
// x^(3/2) = 1/6, P = x^2/15; by force (dF/da = 0, F = -F_c): x^(3/2) = 1/2, P = -x^2/15.
inline double exact_loss(const Contact& c, JkrSeparation rule) {
  const double touching = std::pow(2.0 / 3.0, 4.0 / 3.0);  // x^2 at touching
  const bool by_displacement = rule == JkrSeparation::displacement;
  const double release = std::pow(by_displacement ? 1.0 / 6.0 : 0.5, 4.0 / 3.0);  // x^2 at release
  const double release_primitive = (by_displacement ? 1.0 : -1.0) * release / 15.0;
  const double a0 = equilibrium_radius(c);
  return 4.0 * pull_off_force(c) * a0 * a0 / c.radius * (release_primitive + touching / 10.0);
}

// The same work by Simpson's rule in a on eq 1 and eq 2 in their general form, from touching
// (delta(a) = 0) to the release radius (d(delta)/da = 0, or dF/da = 0).
inline double integrated_loss(const Contact& c, JkrSeparation rule) {
  const double e = c.modulus, w = c.work, r = c.radius;
  const auto force = [&](double a) {
    return 4.0 * e * a * a * a / (3.0 * r) - std::sqrt(8.0 * pi * w * e * a * a * a);
  };
  const auto slope = [&](double a) { return 2.0 * a / r - 0.5 * std::sqrt(2.0 * pi * w / (e * a)); };
  const double touching = std::cbrt(2.0 * pi * w * r * r / e);
  const double release = rule == JkrSeparation::displacement ? std::cbrt(pi * w * r * r / (8.0 * e))
                                                             : std::cbrt(9.0 * pi * w * r * r / (8.0 * e));
  const int n = 100000;
  const double h = (release - touching) / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double a = touching + k * h;
    sum += (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0)) * force(a) * slope(a);
  }
  return sum * h / 3.0;
}

inline double sticking_speed(const Contact& c, JkrSeparation rule) {
  return std::sqrt(2.0 * exact_loss(c, rule) / c.mass);
}

inline double exact_restitution(const Contact& c, JkrSeparation rule, double speed) {
  return std::sqrt(1.0 - exact_loss(c, rule) / (0.5 * c.mass * speed * speed));
}

// Period of small oscillations about the JKR equilibrium, 2 pi (m*/k)^(1/2) with
// k = dF/d(delta) at a = a0 = 3.6 F_c R*/a0^2.
inline double equilibrium_period(const Contact& c) {
  const double a0 = equilibrium_radius(c);
  return 2.0 * pi * std::sqrt(c.mass * a0 * a0 / (3.6 * pull_off_force(c) * c.radius));
}

inline ContactModelSpec jkr_only(JkrSeparation rule) {
  ContactModelSpec spec;
  spec.normal = NormalLaw::jkr;
  spec.separation = rule;
  spec.tangential = false;
  return spec;
}

// The two bodies of `c` approaching head-on at `speed`, their surfaces `gap` apart: a sphere
// falling onto the wall z = 0, or two spheres moving towards each other at speed / 2 each.
inline Simulation approach(const Contact& c, double speed, double gap, JkrSeparation rule,
                           SimulationSettings settings) {
  Particles p;
  if (c.with_wall) {
    p.add({0.0, 0.0, 0.5 + gap}, 0.5, testing::unit_density());
    p.velocity[0] = {0.0, 0.0, -speed};
    return Simulation(std::move(p), {testing::unit_material(kGamma)}, {Wall{}}, jkr_only(rule), settings);
  }
  p.add({0.0, 0.0, 0.0}, 0.5, testing::unit_density());
  p.add({1.0 + gap, 0.0, 0.0}, 0.5, testing::unit_density());
  p.velocity[0] = {0.5 * speed, 0.0, 0.0};
  p.velocity[1] = {-0.5 * speed, 0.0, 0.0};
  return Simulation(std::move(p), {testing::unit_material(kGamma)}, {}, jkr_only(rule), settings);
}

struct Collision {
  bool stuck = true;
  double restitution = 0.0;
  double time_step = 0.0;  // the last step
  std::int64_t steps = 0;
};

// Runs until the contact has let go (and one step more, for the second half kick of the last
// force) or has held for 60 equilibrium periods; the restitution is the separation speed over
// the approach speed.
inline Collision collide(const Contact& c, double speed, double gap, JkrSeparation rule,
                         SimulationSettings settings = {}) {
  Simulation sim = approach(c, speed, gap, rule, settings);
  const double limit = gap / speed + 60.0 * equilibrium_period(c);
  bool touched = false;
  while (sim.time() < limit) {
    sim.step();
    touched = touched || sim.contacts().size() > 0;
    if (touched && sim.contacts().size() == 0) {
      sim.step();
      const Particles& p = sim.particles();
      const double separating = c.with_wall ? p.velocity[0].z : p.velocity[1].x - p.velocity[0].x;
      return {false, separating / speed, sim.time_step(), sim.step_count()};
    }
  }
  return {true, 0.0, sim.time_step(), sim.step_count()};
}

// Starting gaps that put the moment of touching at `phases` evenly spread places within the step
// the bodies approach with (the first step: nothing changes their speeds before they touch).
inline std::vector<double> phase_gaps(const Contact& c, double speed, JkrSeparation rule, int phases,
                                      const SimulationSettings& settings = {}) {
  const double dt = approach(c, speed, 1e-3, rule, settings).time_step();
  std::vector<double> gaps;
  for (int k = 0; k < phases; ++k) gaps.push_back(1e-3 + speed * dt * k / phases);
  return gaps;
}

inline const char* name_of(JkrSeparation rule) {
  return rule == JkrSeparation::displacement ? "displacement" : "force";
}

}  // namespace aerobreak::testing::jkr_cycle
