// JKR normal law (report eqs 1-5) at the level of one contact: closed-form solution of eq 2,
// pull-off force, equilibrium radius and overlap, separation distance, for equal and unequal
// spheres and a sphere on a wall.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "engine/contact/normal_jkr.hpp"
#include "support.hpp"

using namespace aerobreak;
using Catch::Matchers::WithinRel;

namespace {

ContactConstants jkr_contact(double radius_i, double radius_j, const Material& mi, const Material& mj,
                             JkrSeparation rule = JkrSeparation::displacement) {
  const double density = testing::unit_density();
  const auto mass = [&](double r) { return density * 4.0 / 3.0 * std::numbers::pi * r * r * r; };
  const PairMaterial pm = combine(mi, mj);
  ContactConstants c = radius_j > 0.0 ? sphere_pair_constants(radius_i, mass(radius_i), radius_j, mass(radius_j), pm)
                                      : sphere_wall_constants(radius_i, mass(radius_i), pm);
  JkrNormal{rule}.complete(c);
  return c;
}

// Smallest force over overlaps from -break_overlap upwards, by dense sampling.
double most_tensile_force(const ContactConstants& c) {
  const JkrNormal law;
  double lowest = 0.0;
  const double span = 3.0 * c.critical_overlap;
  for (int k = 0; k <= 200000; ++k) {
    const double delta = -c.break_overlap + span * k / 200000.0;
    lowest = std::min(lowest, law.respond(delta, c).force);
  }
  return lowest;
}

}  // namespace

TEST_CASE("closed-form solution of eq 2 inverts delta(a) on the stable branch") {
  const double branch_point = std::pow(6.0, -2.0 / 3.0);  // d(delta)/da = 0: a/a0 = 6^(-2/3)
  for (double x = branch_point; x < 50.0; x *= 1.01) {
    INFO("a/a0 = " << x);
    const double overlap = jkr_overlap_ratio(x);
    // The residual of eq 2 is well conditioned everywhere ...
    CHECK(std::fabs(jkr_overlap_ratio(jkr_radius_ratio(overlap)) - overlap) < 1e-13 * std::max(1.0, x * x));
    // ... a itself only away from the branch point, where d(delta)/da -> 0 costs sqrt(eps).
    CHECK_THAT(jkr_radius_ratio(overlap), WithinRel(x, x > 1.05 * branch_point ? 1e-9 : 1e-6));
  }
  // delta(a) at the branch point is -delta_c (eq 3): -1 / (2 6^(1/3)) in units of a0^2/R*.
  CHECK_THAT(jkr_overlap_ratio(branch_point), WithinRel(-0.5 / std::cbrt(6.0), 1e-12));
}

TEST_CASE("identical spheres reproduce the report's eqs 3-5 exactly") {
  for (double gamma : {1e-4, 1e-3, 1e-2}) {
    const Material m = testing::unit_material(gamma, 0.3);
    const ContactConstants c = jkr_contact(0.5, 0.5, m, m);
    const double d = 1.0, pi = std::numbers::pi, nu2 = 1.0 - 0.3 * 0.3;
    const double a0 = std::cbrt(9.0 * pi * gamma * nu2 * d * d / (8.0 * m.youngs_modulus));  // eq 4
    CHECK_THAT(c.equilibrium_radius, WithinRel(a0, 1e-12));
    CHECK_THAT(c.pull_off_force, WithinRel(3.0 * pi * gamma * d / 4.0, 1e-12));              // eq 5
    CHECK_THAT(c.critical_overlap, WithinRel(2.0 * a0 * a0 / (d * std::cbrt(6.0)), 1e-12));  // eq 3
  }
}

TEST_CASE("force, overlap and radius of the law obey eq 1 in its general form") {
  const Material m = testing::unit_material(0.01);
  for (const auto& [ri, rj] : {std::pair{0.5, 0.5}, std::pair{0.5, 1.5}, std::pair{0.3, 0.0}}) {
    const ContactConstants c = jkr_contact(ri, rj, m, m);
    const JkrNormal law;
    for (double delta : {-0.9 * c.critical_overlap, 0.0, 0.5 * c.critical_overlap, 10.0 * c.critical_overlap}) {
      const auto r = law.respond(delta, c);
      const double a = r.contact_radius;
      const double e = c.modulus, w = c.work_of_adhesion, rs = c.radius, pi = std::numbers::pi;
      // docs/MODEL.md section 2, eq 1 (general form): F = 4E*a^3/(3R*) - sqrt(8 pi w E* a^3)
      CHECK_THAT(r.force, WithinRel(4.0 * e * a * a * a / (3.0 * rs) - std::sqrt(8.0 * pi * w * e * a * a * a), 1e-9));
      // eq 2 (general form): delta = a^2/R* - sqrt(2 pi w a / E*)
      CHECK(std::fabs(a * a / rs - std::sqrt(2.0 * pi * w * a / e) - delta) < 1e-12 * c.critical_overlap + 1e-15);
    }
  }
}

TEST_CASE("pull-off force is F_c = 1.5 pi w R* for equal, unequal spheres and a wall") {
  const Material m = testing::unit_material(0.01);
  for (const auto& [ri, rj] : {std::pair{0.5, 0.5}, std::pair{0.5, 2.0}, std::pair{0.5, 0.0}}) {
    const ContactConstants c = jkr_contact(ri, rj, m, m);
    INFO("R_i = " << ri << ", R_j = " << rj);
    CHECK_THAT(most_tensile_force(c), WithinRel(-1.5 * std::numbers::pi * c.work_of_adhesion * c.radius, 1e-6));
  }
}

TEST_CASE("zero force at the equilibrium radius a0 and overlap a0^2/(3 R*)") {
  const Material m = testing::unit_material(0.001);
  for (double rj : {0.5, 1.0, 0.0}) {
    const ContactConstants c = jkr_contact(0.5, rj, m, m);
    const double equilibrium = c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius);
    const auto r = JkrNormal{}.respond(equilibrium, c);
    CHECK(std::fabs(r.force) < 1e-9 * c.pull_off_force);
    CHECK_THAT(r.contact_radius, WithinRel(c.equilibrium_radius, 1e-9));
  }
}

TEST_CASE("separation rules: delta_c (eq 3) by default, F = -F_c as the named alternative") {
  const Material m = testing::unit_material(0.01);
  const ContactConstants by_displacement = jkr_contact(0.5, 0.5, m, m, JkrSeparation::displacement);
  CHECK(by_displacement.break_overlap == by_displacement.critical_overlap);
  // At the break point of the displacement rule a = a0 6^(-2/3) and F = -(5/9) F_c.
  const auto at_break = JkrNormal{}.respond(-by_displacement.critical_overlap, by_displacement);
  CHECK_THAT(at_break.force, WithinRel(-5.0 / 9.0 * by_displacement.pull_off_force, 1e-6));

  const ContactConstants by_force = jkr_contact(0.5, 0.5, m, m, JkrSeparation::force);
  const auto at_force_break = JkrNormal{JkrSeparation::force}.respond(-by_force.break_overlap, by_force);
  CHECK_THAT(at_force_break.force, WithinRel(-by_force.pull_off_force, 1e-9));
  CHECK_THAT(at_force_break.contact_radius, WithinRel(by_force.equilibrium_radius / std::cbrt(4.0), 1e-9));
  CHECK(by_force.break_overlap < by_force.critical_overlap);
}

TEST_CASE("stored energy is the work of eq 1 along eq 2, zero at touching") {
  const Material m = testing::unit_material(0.01);
  const ContactConstants c = jkr_contact(0.5, 0.5, m, m);
  const JkrNormal law;
  CHECK(std::fabs(law.respond(0.0, c).energy) < 1e-15);
  // Trapezoidal quadrature of F d(delta) from 0 to delta.
  for (double target : {-c.critical_overlap, 0.3 * c.critical_overlap, 5.0 * c.critical_overlap}) {
    const int steps = 20000;
    double work = 0.0;
    for (int k = 0; k < steps; ++k) {
      const double d0 = target * k / steps, d1 = target * (k + 1) / steps;
      work += 0.5 * (law.respond(d0, c).force + law.respond(d1, c).force) * (d1 - d0);
    }
    CHECK_THAT(law.respond(target, c).energy, WithinRel(work, 1e-5));
  }
}
