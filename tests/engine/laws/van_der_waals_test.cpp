// Hamaker van der Waals attraction between spheres outside contact (Derjaguin approximation:
// F = A R* / (6 z^2), Hamaker 1937; Israelachvili ch. 13), with the minimum separation z0 of the
// report's eq 6 and a cut-off: the law, its energy, and two spheres pulled into contact.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/contact/van_der_waals.hpp"
#include "law_support.hpp"

using namespace aerobreak;
using namespace aerobreak::laws;

namespace {

// Hamaker constant consistent with the surface energy: w = A / (12 pi z0^2) = 2 gamma, so that
// the attraction at contact is the DMT pull-off 2 pi w R*.
constexpr double gamma_over_kn = 1e-4;
constexpr double z0 = 4e-3;
const VanDerWaals law{24.0 * std::numbers::pi * gamma_over_kn * z0 * z0, z0, 0.05};
constexpr double reduced_radius = 0.25;  // two unit spheres

// Composite Simpson rule of f over [a, b] with n (even) intervals.
template <class F>
double simpson(F f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
  return sum * h / 3.0;
}

}  // namespace

TEST_CASE(
    "van der Waals attraction is A Reff/(6 z^2) between z0 and the cut-off and is constant below and zero beyond") {
  const double scale = law.hamaker * reduced_radius / 6.0;
  for (double gap : {z0, 1.5 * z0, 0.01, 0.03, 0.0499}) {
    INFO("z = " << gap);
    CHECK(law.at_gap(gap, reduced_radius).attraction == Approx(scale / (gap * gap)).epsilon(1e-14));
  }
  for (double gap : {0.9 * z0, 0.1 * z0, 0.0, -0.01}) {
    INFO("z = " << gap);
    CHECK(law.at_gap(gap, reduced_radius).attraction == Approx(scale / (z0 * z0)).epsilon(1e-14));
  }
  for (double gap : {law.cutoff, 0.06, 1.0}) {
    INFO("z = " << gap);
    CHECK(law.at_gap(gap, reduced_radius).attraction == 0.0);
    CHECK(law.at_gap(gap, reduced_radius).energy == 0.0);
  }
  // A wall is a sphere of infinite radius: R* = R_i.
  CHECK(law.at_gap(0.01, 0.5).attraction == Approx(2.0 * law.at_gap(0.01, reduced_radius).attraction).epsilon(1e-14));
}

// The energy is the work against the attraction from the cut-off: E(z) = -int_z^cut F dz', so
// dE/dz = F (the force on the gap coordinate, -dE/dz, pulls the surfaces together), continuous at
// z0 and zero at the cut-off. Central differences (h = 1e-4 z: relative error ~h^2/z^2 = 1e-8)
// and Simpson quadrature (10^4 intervals on a smooth integrand) are far below the 1e-6 checked.
TEST_CASE("van der Waals energy is minus the integral of the attraction from the cut-off") {
  const auto force = [](double z) { return law.at_gap(z, reduced_radius).attraction; };
  const auto energy = [](double z) { return law.at_gap(z, reduced_radius).energy; };
  for (double gap : {0.3 * z0, 0.8 * z0, 1.2 * z0, 0.01, 0.04}) {
    INFO("z = " << gap);
    const double h = 1e-4 * gap;
    CHECK((energy(gap + h) - energy(gap - h)) / (2.0 * h) == Approx(force(gap)).epsilon(1e-6));
    const double top = law.cutoff * (1.0 - 1e-15);  // the force drops to zero at the cut-off itself
    const double integral =
        gap < z0 ? simpson(force, gap, z0, 10000) + simpson(force, z0, top, 10000) : simpson(force, gap, top, 10000);
    CHECK(energy(gap) == Approx(-integral).epsilon(1e-6));
    CHECK(energy(gap) < 0.0);
  }
  CHECK(energy(z0 * (1.0 - 1e-12)) == Approx(energy(z0 * (1.0 + 1e-12))).epsilon(1e-9));
  CHECK(std::fabs(energy(law.cutoff * (1.0 - 1e-12))) < 1e-9 * std::fabs(energy(z0)));
}

namespace {

// Two unit spheres at rest, surfaces `gap` apart along x, with van der Waals attraction and JKR
// contacts.
Simulation attracted_pair(double gap) {
  ContactModelSpec spec;
  spec.van_der_waals = true;
  spec.hamaker = law;
  Particles p;
  p.add({0.0, 0.0, 0.0}, unit_radius, unit_density);
  p.add({2.0 * unit_radius + gap, 0.0, 0.0}, unit_radius, unit_density);
  return Simulation(std::move(p), {reduced_material(gamma_over_kn, 0.3)}, {}, spec);
}

}  // namespace

// Two spheres at rest with a gap inside the cut-off start with the force A R*/(6 z^2) on each,
// along the line of centres, equal and opposite; they accelerate towards each other with zero
// total momentum and touch, forming a contact, no later than they would under the initial
// (weakest) attraction held constant: t <= sqrt(2 z m* / F(z)).
TEST_CASE("two spheres at rest within the van der Waals range accelerate towards each other and touch") {
  const double gap = 0.005;
  Simulation sim = attracted_pair(gap);
  const Particles& p = sim.particles();
  const double pull = law.hamaker * reduced_radius / (6.0 * gap * gap);
  CHECK(p.force[0].x == Approx(pull).epsilon(1e-10));
  CHECK(p.force[1].x == Approx(-pull).epsilon(1e-10));
  CHECK(p.force[0].y == 0.0);
  CHECK(p.force[0].z == 0.0);
  const double mass = p.mass[0] * p.mass[1] / (p.mass[0] + p.mass[1]);
  const double latest = std::sqrt(2.0 * gap * mass / pull);
  while (sim.pair_events().made == 0 && sim.time() < latest) {
    sim.step();
    CHECK(p.velocity[0].x > 0.0);
    CHECK(p.velocity[1].x < 0.0);
    CHECK(std::fabs(p.mass[0] * p.velocity[0].x + p.mass[1] * p.velocity[1].x) < 1e-15);
  }
  CHECK(sim.pair_events().made == 1);
  CHECK(sim.contacts().size() == 1);
  CHECK(sim.time() < latest);
}

// The energy balance must hold across the hand-over from the van der Waals law to the contact law.
// The van der Waals energy just before touching, -(A R*/(6 z0)) (2 - z0/z_cut), leaves the van der
// Waals term when the contact forms (the contact's own energy starts at zero on touching); the
// ledger books it as van_der_waals_handover. Before contact the balance moves by ~1e-4 of that
// energy (checked to 1e-3). Across the hand-over the force switches from F_vdW(z0) to the JKR
// snap-in force between two steps, an energy error of at most (F_c + F_vdW(z0)) v dt; with this
// Hamaker constant (A = 24 pi gamma z0^2, so w = A / (12 pi z0^2)) the spheres arrive moving about
// z0 per step, so that bound, not a fixed share of the well depth, sets the tolerance.
TEST_CASE("the energy balance holds when van der Waals attraction hands over to a contact") {
  Simulation sim = attracted_pair(0.005);
  const double initial = sim.energy().balance();
  const double scale = std::fabs(law.at_gap(0.0, reduced_radius).energy);
  while (sim.pair_events().made == 0 && sim.step_count() < 10000) {
    sim.step();
    if (sim.pair_events().made == 0) REQUIRE(sim.energy().balance() == Approx(initial).margin(1e-3 * scale));
  }
  REQUIRE(sim.pair_events().made == 1);
  const Particles& p = sim.particles();
  const double speed = std::fabs(p.velocity[1].x - p.velocity[0].x);
  const double pull_off = 1.5 * std::numbers::pi * 2.0 * gamma_over_kn * reduced_radius;
  const double switch_error = (pull_off + law.at_gap(0.0, reduced_radius).attraction) * speed * sim.time_step();
  const double overlap = 2.0 * unit_radius - std::fabs(p.position[1].x - p.position[0].x);
  CHECK(sim.energy().dissipation.van_der_waals_handover == Approx(law.at_gap(-overlap, reduced_radius).energy));
  sim.run(20);
  CHECK(sim.energy().balance() == Approx(initial).margin(0.01 * scale + switch_error));
}
