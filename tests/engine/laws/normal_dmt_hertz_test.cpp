// Plain Hertz and DMT normal laws (report eq 1 without and with a constant adhesive pull, section
// 2.1): force, contact radius, pull-off force, energy as the work of the force, and the Hertz
// impact time.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "engine/contact/normal_dmt.hpp"
#include "engine/contact/normal_hertz.hpp"
#include "law_support.hpp"

using namespace aerobreak;
using namespace aerobreak::laws;

namespace {

// int_0^delta f by the composite Simpson rule in the variable u = sqrt(delta'), which makes the
// delta^(3/2) integrands smooth (f(u^2) 2u is a polynomial in u for Hertz): exact to round-off.
template <class F>
double work_of(F f, double delta, int n = 2000) {
  const double top = std::sqrt(delta);
  const double h = top / n;
  const auto g = [&](double u) { return f(u * u) * 2.0 * u; };
  double sum = g(0.0) + g(top);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * g(k * h);
  return sum * h / 3.0;
}

}  // namespace

// Eq 1 without adhesion, with eq 7 and delta = 4a^2/d for identical spheres: F = k_n delta^(3/2) /
// sqrt(d), a = sqrt(d delta) / 2. Generally F = (4/3) E* sqrt(R*) delta^(3/2), a = sqrt(R* delta).
TEST_CASE("Hertz force is (4/3) Eeff sqrt(Reff) delta^(3/2) and k_n delta^(3/2)/sqrt(d) for identical spheres") {
  const HertzNormal hertz;
  for (double diameter : {1.0, 3.0}) {
    const Material m = reduced_material(0.0, 0.3);  // E chosen so that k_n = 1 for d = 1
    const double k_n = normal_stiffness(m, diameter);
    const ContactConstants c = contact_constants(hertz, m, m, 0.5 * diameter, 0.5 * diameter);
    for (double overlap : {1e-6, 1e-3, 0.05}) {
      INFO("d = " << diameter << ", delta = " << overlap);
      const NormalResponse r = hertz.respond(overlap, c);
      CHECK(r.force == Approx(k_n * std::pow(overlap, 1.5) / std::sqrt(diameter)).epsilon(1e-13));
      CHECK(r.contact_radius == Approx(0.5 * std::sqrt(diameter * overlap)).epsilon(1e-13));
      CHECK(r.coulomb_load == r.force);
    }
  }
  // Unequal spheres of different materials, and a wall.
  const Material soft = reduced_material(0.0, 0.2);
  Material hard = reduced_material(0.0, 0.4);
  hard.youngs_modulus *= 7.0;
  const double e_star = 1.0 / ((1.0 - 0.04) / soft.youngs_modulus + (1.0 - 0.16) / hard.youngs_modulus);
  for (double radius_j : {1.7, 0.0}) {
    INFO("R_j = " << radius_j);
    const ContactConstants c = contact_constants(hertz, soft, hard, 0.6, radius_j);
    const double r_star = radius_j > 0.0 ? 0.6 * radius_j / (0.6 + radius_j) : 0.6;
    const double overlap = 2e-3;
    CHECK(hertz.respond(overlap, c).force ==
          Approx(4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(overlap, 1.5)).epsilon(1e-13));
    CHECK(hertz.respond(overlap, c).contact_radius == Approx(std::sqrt(r_star * overlap)).epsilon(1e-13));
  }
  CHECK(hertz.respond(-1e-3, contact_constants(hertz, soft, soft)).force == 0.0);
}

// DMT: the Hertz repulsion minus a constant pull F_c = 2 pi w R* while the surfaces overlap; for
// identical spheres (w = 2 gamma, R* = d/4) that is the report's DMT pull-off pi gamma d. The
// contact radius is Hertzian and a0 is where the net force vanishes.
TEST_CASE("DMT pull-off is 2 pi w Reff (pi gamma d for identical spheres) on top of Hertz") {
  const DmtNormal dmt;
  const HertzNormal hertz;
  for (double gamma : {1e-4, 1e-2})
    for (double diameter : {1.0, 2.5}) {
      INFO("gamma = " << gamma << ", d = " << diameter);
      const Material m = reduced_material(gamma, 0.3);
      const ContactConstants c = contact_constants(dmt, m, m, 0.5 * diameter, 0.5 * diameter);
      const ContactConstants h = contact_constants(hertz, m, m, 0.5 * diameter, 0.5 * diameter);
      CHECK(c.pull_off_force == Approx(std::numbers::pi * gamma * diameter).epsilon(1e-14));
      CHECK(dmt.respond(0.0, c).force == Approx(-c.pull_off_force).epsilon(1e-14));
      CHECK(c.break_overlap == 0.0);
      for (double overlap : {1e-6, 1e-4, 1e-2}) {
        const NormalResponse r = dmt.respond(overlap, c);
        CHECK(r.force == Approx(hertz.respond(overlap, h).force - c.pull_off_force).epsilon(1e-13));
        CHECK(r.contact_radius == Approx(hertz.respond(overlap, h).contact_radius).epsilon(1e-14));
        CHECK(r.coulomb_load == Approx(hertz.respond(overlap, h).force).epsilon(1e-13));
      }
      const double a0 = c.equilibrium_radius;
      const double zero_load = a0 * a0 / c.radius;
      CHECK(std::fabs(dmt.respond(zero_load, c).force) < 1e-12 * c.pull_off_force);
      CHECK(dmt.respond(zero_load, c).contact_radius == Approx(a0).epsilon(1e-14));
    }
}

// The stored energy is the work done against the force from touching: E(delta) = int_0^delta F,
// for Hertz (0.4 F delta) and DMT (0.4 F_Hertz delta - F_c delta).
TEST_CASE("Hertz and DMT energy is the integral of the force over the overlap") {
  const Material m = reduced_material(1e-3, 0.3);
  const HertzNormal hertz;
  const DmtNormal dmt;
  for (double radius_j : {0.5, 0.0}) {
    const ContactConstants h = contact_constants(hertz, m, m, 0.5, radius_j);
    const ContactConstants d = contact_constants(dmt, m, m, 0.5, radius_j);
    for (double overlap : {1e-5, 1e-3, 2e-2, 0.1}) {
      INFO("R_j = " << radius_j << ", delta = " << overlap);
      const double hertz_work = work_of([&](double x) { return hertz.respond(x, h).force; }, overlap);
      CHECK(hertz.respond(overlap, h).energy == Approx(hertz_work).epsilon(1e-10));
      const double dmt_work = work_of([&](double x) { return dmt.respond(x, d).force; }, overlap);
      CHECK(dmt.respond(overlap, d).energy ==
            Approx(dmt_work).epsilon(1e-10).margin(1e-12 * d.pull_off_force * overlap));
    }
  }
}

// Hertz impact of a sphere on a wall at speed v (Hertz 1882; Johnson, Contact Mechanics, 11.4):
// deepest overlap delta_m = (5 m* v^2 / (4 K))^(2/5) and contact time
// t_c = 2 (delta_m / v) int_0^1 du / sqrt(1 - u^(5/2)) = (4/5) B(2/5, 1/2) delta_m / v
// = 2.9432 delta_m / v. At 200 steps per period the contact time is resolved to +- 1 step, and
// the deepest overlap to ~(pi/170)^2 relative from sampling at the steps.
TEST_CASE("a Hertz impact lasts the Hertz contact time and reaches the Hertz overlap") {
  ContactModelSpec spec;
  spec.normal = NormalLaw::hertz;
  spec.tangential = false;
  const Material m = reduced_material(0.0, 0.3);
  const double speed = 0.02;
  SimulationSettings settings;
  settings.steps_per_period = 200.0;
  const Vec3 velocity{0.0, 0.0, -speed};
  Simulation sim =
      sphere_over_floor(spec, m, 0.5 * speed * sphere_over_floor(spec, m, 1.0, velocity, false, settings).time_step(),
                        velocity, false, settings);
  const ContactConstants c = contact_constants(HertzNormal{}, m, m, unit_radius, 0.0);
  const double deepest = std::pow(5.0 * c.mass * speed * speed / (4.0 * c.hertz_coefficient), 0.4);
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  const double duration = 0.8 * beta * deepest / speed;

  double reached = 0.0;
  int contact_steps = 0;
  bool touched = false;
  for (int s = 0; s < 100000; ++s) {
    sim.step();
    const bool in_contact = sim.contacts().size() > 0;
    touched = touched || in_contact;
    if (in_contact) ++contact_steps;
    reached = std::max(reached, unit_radius - sim.particles().position[0].z);
    if (touched && !in_contact) break;
  }
  const double dt = sim.time_step();
  CHECK(contact_steps * dt == Approx(duration).margin(1.01 * dt));
  CHECK(reached == Approx(deepest).epsilon(1e-3));
}
