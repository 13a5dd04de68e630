// The energy scales and dimensionless groups of an impact (docs/MODEL.md 1.3) and its
// small-strain check (docs/MODEL.md 3.7), against hand computations.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "engine/core/material.hpp"
#include "engine/core/material_table.hpp"
#include "engine/core/units.hpp"
#include "engine/impact/contact_scales.hpp"

using namespace aerobreak;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double pi = std::numbers::pi;
const double unit_mass = 1.0;  // reduced: a primary of diameter 1 has mass 1

// Two reduced primaries of diameter 1 (R* = 1/4) of gamma/k_n = gamma, completed by the law.
ContactConstants primary_pair(const ContactForces& law, double gamma) {
  const MaterialTable materials({reduced_material(gamma, 0.3)});
  ContactConstants c = sphere_pair_constants(0.5, unit_mass, 0.5, unit_mass, materials.pair(0, 0));
  law.complete(c);
  return c;
}

ContactModelSpec jkr(JkrSeparation separation = JkrSeparation::displacement) {
  ContactModelSpec spec;
  spec.normal = NormalLaw::jkr;
  spec.separation = separation;
  return spec;
}

// The work done on the contact as the overlap goes from `from` down to `to` (< from) along the
// law: -integral of F d(delta) from `to` to `from`, by Simpson's rule in u = sqrt(delta - to),
// which takes out the square-root end point of the JKR curve at its turning point.
double work_pulling(const ContactForces& law, const ContactConstants& c, double from, double to) {
  const int intervals = 20000;
  const double top = std::sqrt(from - to), h = top / intervals;
  double sum = 0.0;
  for (int k = 0; k <= intervals; ++k) {
    const double u = k * h;
    const double weight = (k == 0 || k == intervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += weight * law.normal_response(to + u * u, c).force * 2.0 * u;  // d(delta) = 2u du
  }
  return -sum * h / 3.0;
}

}  // namespace

TEST_CASE("E_break = 1.5426 F_c delta_c: the JKR work from the zero-load equilibrium to separation at -delta_c") {
  const auto law = make_contact_forces(jkr(), NormalLaw::jkr);
  const ContactConstants c = primary_pair(*law, 0.001);
  const double scale = c.pull_off_force * c.critical_overlap;
  // Zero load: x = a/a0 = 1, delta = a0^2/(3 R*) (docs/MODEL.md 3.2).
  const double equilibrium = c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius);
  const double integrated = work_pulling(*law, c, equilibrium, -c.critical_overlap) / scale;
  // Closed form: 8 6^(1/3) [P(6^(-2/3)) - P(1)] with P(1) = -1/10 and P(6^(-2/3)) = 6^(-4/3)/15,
  // that is 0.8 6^(1/3) + 4/45 = 1.542586 (docs/MODEL.md 3.4).
  const double closed_form = 0.8 * std::cbrt(6.0) + 4.0 / 45.0;
  CHECK_THAT(integrated, WithinRel(closed_form, 1e-6));
  CHECK_THAT(closed_form, WithinAbs(1.54, 0.005));  // the coefficient of Chokshi et al. 1993, Wada et al. 2007

  const ContactEnergies e = contact_energies(
      *law, sphere_pair_constants(0.5, 1.0, 0.5, 1.0, MaterialTable({reduced_material(0.001, 0.3)}).pair(0, 0)), 0.0);
  CHECK_THAT(e.equilibrium_overlap, WithinRel(equilibrium, 1e-12));
  CHECK_THAT(e.breaking_energy / scale, WithinRel(closed_form, 1e-9));
  CHECK(std::isnan(e.rolling_energy));
}

TEST_CASE("E_break with the force-controlled separation is the work to F = -F_c, where the contact lets go") {
  const auto law = make_contact_forces(jkr(JkrSeparation::force), NormalLaw::jkr);
  const ContactConstants c = primary_pair(*law, 0.01);
  const double equilibrium = c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius);
  const double integrated = work_pulling(*law, c, equilibrium, -c.break_overlap);
  const ContactEnergies e = contact_energies(
      *law, sphere_pair_constants(0.5, 1.0, 0.5, 1.0, MaterialTable({reduced_material(0.01, 0.3)}).pair(0, 0)), 0.0);
  CHECK_THAT(e.breaking_energy, WithinRel(integrated, 1e-6));
  CHECK_THAT(e.breaking_energy / (c.pull_off_force * c.critical_overlap), WithinAbs(1.0691, 1e-4));
}

TEST_CASE("the contact scales of the reference pair of the literature (gamma/k_n = 0.001)") {
  // d = 1, m = 1, E = 2.73e5, nu = 0.3, gamma = 100 is gamma/k_n = 0.001 with k_n = 1e5 (eq 7):
  // F_c delta_c = 2.893, E_break = 1.54 F_c delta_c, E_roll = 6 pi^2 gamma R* xi_crit = 14.8 for
  // xi_crit = 0.01 d; in k_n d^2 all are 1e5 times smaller.
  const auto law = make_contact_forces(jkr(), NormalLaw::jkr);
  const MaterialTable materials({reduced_material(0.001, 0.3)});
  const ContactEnergies e =
      contact_energies(*law, sphere_pair_constants(0.5, 1.0, 0.5, 1.0, materials.pair(0, 0)), 0.01);
  CHECK_THAT(e.pull_off_force * e.critical_overlap * 1e5, WithinRel(2.893, 5e-4));
  CHECK_THAT(e.breaking_energy * 1e5, WithinRel(1.5426 * 2.893, 5e-4));
  CHECK_THAT(e.rolling_energy, WithinRel(6.0 * pi * pi * 0.001 * 0.25 * 0.01, 1e-12));
  CHECK_THAT(e.rolling_energy * 1e5, WithinRel(14.8, 2e-3));
  // F_c = 3 pi gamma R* (eq 5 with w = 2 gamma).
  CHECK_THAT(e.pull_off_force, WithinRel(3.0 * pi * 0.001 * 0.25, 1e-12));
}

TEST_CASE("E_break of the DMT law is 3/5 F_c delta_0, a law without adhesion has none") {
  ContactModelSpec spec;
  spec.normal = NormalLaw::dmt;
  const auto dmt = make_contact_forces(spec, NormalLaw::dmt);
  const MaterialTable materials({reduced_material(0.001, 0.3)});
  const ContactEnergies e =
      contact_energies(*dmt, sphere_pair_constants(0.5, 1.0, 0.5, 1.0, materials.pair(0, 0)), 0.0);
  // Hertz K delta0^(3/2) = F_c at zero load; U(delta0) = (2/5) K delta0^(5/2) - F_c delta0; the
  // contact lets go at delta = 0, where U = 0.
  const double fc = 2.0 * pi * 0.002 * 0.25;
  const double k = 4.0 / 3.0 * 1.5 * std::sqrt(0.25);  // K = (4/3) E* sqrt(R*) = 1 (docs/MODEL.md 1.1)
  const double delta0 = std::cbrt(fc * fc / (k * k));
  CHECK_THAT(e.pull_off_force, WithinRel(fc, 1e-12));
  CHECK_THAT(e.equilibrium_overlap, WithinRel(delta0, 1e-9));
  CHECK_THAT(e.breaking_energy, WithinRel(0.6 * fc * delta0, 1e-9));

  spec.normal = NormalLaw::hertz;
  const auto hertz = make_contact_forces(spec, NormalLaw::hertz);
  const ContactEnergies none =
      contact_energies(*hertz, sphere_pair_constants(0.5, 1.0, 0.5, 1.0, materials.pair(0, 0)), 0.0);
  CHECK(none.breaking_energy == 0.0);
  const EnergyGroups g = energy_groups(1.0, 10, none);
  CHECK(std::isnan(g.energy_per_contact));
  CHECK(std::isnan(g.energy_over_rolling));
}

TEST_CASE("the energy groups are E_kin / (N_c E_break) and E_kin / E_roll") {
  ContactEnergies e;
  e.breaking_energy = 4.0e-5;
  e.rolling_energy = 3.0e-4;
  // 32 primaries at 0.05 d/tau: E_kin = 32 x 0.0025 / 2 = 0.04; 31 contacts.
  const EnergyGroups g = energy_groups(0.04, 31, e);
  CHECK_THAT(g.energy_per_contact, WithinRel(0.04 / (31 * 4.0e-5), 1e-14));
  CHECK_THAT(g.energy_over_rolling, WithinRel(0.04 / 3.0e-4, 1e-14));
  CHECK(std::isnan(energy_groups(0.04, 0, e).energy_per_contact));
}

TEST_CASE("the small-strain check: contact radius and overlap over the primary radius") {
  const double gamma = 0.01;
  const MaterialTable materials({reduced_material(gamma, 0.3), reduced_material(gamma, 0.3)});
  Particles p;
  for (int k = 0; k < 3; ++k) p.add({static_cast<double>(k), 0.0, 0.5}, 0.5, 6.0 / pi);
  Wall wall;
  wall.material = 1;
  const ContactModelSpec spec = jkr();
  // Zero load: a = a0, a0 = (9 pi w R*^2 / (2 E*))^(1/3) with w = 2 gamma, E* = 3/2; delta = a0^2/(3 R*).
  const auto a0 = [&](double reduced_radius) {
    return std::cbrt(9.0 * pi * 2.0 * gamma * reduced_radius * reduced_radius / 3.0);
  };
  const double pair_a0 = a0(0.25), wall_a0 = a0(0.5);

  SECTION("at rest: pairs inside the range, the same primary on an adhesive wall of its material outside it") {
    DeepestOverlaps deepest;
    deepest.pair = pair_a0 * pair_a0 / (3.0 * 0.25) / 0.25;  // over R*
    deepest.wall = wall_a0 * wall_a0 / (3.0 * 0.5) / 0.5;
    const SmallStrainCheck check = check_small_strain(deepest, p, materials, wall, spec);
    CHECK_THAT(check.pair.contact_radius_ratio, WithinRel(pair_a0 / 0.5, 1e-9));  // 0.455
    CHECK_THAT(check.pair.overlap_ratio, WithinRel(*deepest.pair / 2.0, 1e-14));  // R* = R/2
    CHECK_THAT(check.wall.contact_radius_ratio, WithinRel(wall_a0 / 0.5, 1e-9));  // 0.722
    CHECK_THAT(check.wall.overlap_ratio, WithinRel(*deepest.wall, 1e-14));        // R* = R
    CHECK(check.pair.contact_radius_ratio < 0.5);
    CHECK(check.worst.contact_radius_ratio == check.wall.contact_radius_ratio);
    CHECK_FALSE(check.within);
    CHECK_FALSE(check.bound);
  }
  SECTION("without wall contacts only the pairs count") {
    DeepestOverlaps deepest;
    deepest.pair = pair_a0 * pair_a0 / (3.0 * 0.25) / 0.25;
    const SmallStrainCheck check = check_small_strain(deepest, p, materials, wall, spec);
    CHECK(check.wall.contact_radius_ratio == 0.0);
    CHECK(check.within);
  }
  SECTION("a wall without adhesion: Hertz, a = sqrt(R delta)") {
    wall.adhesive = false;
    DeepestOverlaps deepest;
    deepest.wall = 0.16;
    CHECK_THAT(check_small_strain(deepest, p, materials, wall, spec).wall.contact_radius_ratio, WithinRel(0.4, 1e-12));
    CHECK(check_small_strain(deepest, p, materials, wall, spec).within);
    deepest.wall = 0.36;
    CHECK_THAT(check_small_strain(deepest, p, materials, wall, spec).wall.contact_radius_ratio, WithinRel(0.6, 1e-12));
    CHECK_FALSE(check_small_strain(deepest, p, materials, wall, spec).within);
    deepest.wall = 0.55;  // over the overlap limit too
    CHECK(check_small_strain(deepest, p, materials, wall, spec).worst.overlap_ratio > 0.5);
  }
  SECTION("primaries of several radii: the extreme pair bounds the ratios") {
    p.radius[0] = 0.3;
    p.radius[2] = 0.7;
    DeepestOverlaps deepest;
    deepest.pair = 0.1;
    const SmallStrainCheck check = check_small_strain(deepest, p, materials, wall, spec);
    CHECK(check.bound);
    // R*/R of the smaller primary of the most unequal pair: 0.7/(0.3 + 0.7).
    CHECK_THAT(check.pair.overlap_ratio, WithinRel(0.1 * 0.7, 1e-14));
  }
}
