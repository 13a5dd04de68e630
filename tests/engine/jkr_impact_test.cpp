// A sphere against an adhesive wall with the JKR law (report eqs 1-5): equilibrium overlap,
// pull-off under a constant load and separation distance. Restitution against the energy of the
// JKR loop: jkr_restitution_test.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "engine/dem/simulation.hpp"
#include "support.hpp"

using namespace aerobreak;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kGamma = 0.01;  // gamma / k_n
const double pi = std::numbers::pi;

struct SphereOnWall {
  double modulus, work, radius, mass;  // E*, w, R* (= R for a wall), m* (= m)
};

SphereOnWall sphere_on_wall() {
  const Material m = testing::unit_material(kGamma);
  const PairMaterial pm = combine(m, m);
  return {pm.modulus, pm.work_of_adhesion, 0.5, 1.0};
}

ContactModelSpec jkr_only(JkrSeparation rule = JkrSeparation::displacement) {
  ContactModelSpec spec;
  spec.normal = NormalLaw::jkr;
  spec.separation = rule;
  spec.tangential = false;
  return spec;
}

Simulation sphere_above_wall(double gap, double speed, ContactModelSpec spec, SimulationSettings settings = {}) {
  Particles p;
  p.add({0.0, 0.0, 0.5 + gap}, 0.5, testing::unit_density());
  p.velocity[0] = {0.0, 0.0, -speed};
  if (settings.steps_per_period == 50.0) settings.steps_per_period = 400.0;
  return Simulation(std::move(p), {testing::unit_material(kGamma)}, {Wall{}}, spec, settings);
}

double overlap_of(const Simulation& sim) { return 0.5 - sim.particles().position[0].z; }

}  // namespace

TEST_CASE("a sphere settles at the JKR equilibrium overlap a0^2/(3R*) on an adhesive wall") {
  ContactModelSpec spec = jkr_only();
  spec.damping = DampingLaw::viscoelastic;
  spec.dissipative_time = 2.0;
  SimulationSettings settings;
  settings.speed_scale = 0.05;
  Simulation sim = sphere_above_wall(-1e-4, 0.0, spec, settings);
  sim.run(200000);
  const SphereOnWall s = sphere_on_wall();
  const double a0 = std::cbrt(9.0 * pi * s.work * s.radius * s.radius / (2.0 * s.modulus));  // eq 4
  CHECK_THAT(overlap_of(sim), WithinRel(a0 * a0 / (3.0 * s.radius), 1e-6));
  CHECK(std::fabs(sim.particles().velocity[0].z) < 1e-9);
}

TEST_CASE("under a steady pull the contact holds below F_c and lets go above it") {
  const SphereOnWall s = sphere_on_wall();
  const double pull_off = 1.5 * pi * s.work * s.radius;  // eq 5, F_c = 1.5 pi w R*
  for (auto rule : {JkrSeparation::displacement, JkrSeparation::force}) {
    for (double load : {0.97, 1.03}) {
      // Overdamped (critical is A ~ 5 here), so the sphere creeps from its unloaded equilibrium
      // to the loaded one without overshoot; a contact cannot be formed in tension directly.
      ContactModelSpec spec = jkr_only(rule);
      spec.damping = DampingLaw::viscoelastic;
      spec.dissipative_time = 20.0;
      SimulationSettings settings;
      settings.speed_scale = 0.05;
      settings.body.gravity = {0.0, 0.0, load * pull_off / s.mass};  // pulls the sphere off the wall
      const double a0 = std::cbrt(9.0 * pi * s.work * s.radius * s.radius / (2.0 * s.modulus));
      Simulation sim = sphere_above_wall(-a0 * a0 / (3.0 * s.radius), 0.0, spec, settings);
      sim.run(200000);
      INFO("load / F_c = " << load << ", rule " << static_cast<int>(rule));
      CHECK((sim.contacts().size() == 1) == (load < 1.0));
    }
  }
}

TEST_CASE("a contact in tension separates at delta = -delta_c, or at F = -F_c by the named rule") {
  const SphereOnWall s = sphere_on_wall();
  const double a0 = std::cbrt(9.0 * pi * s.work * s.radius * s.radius / (2.0 * s.modulus));
  const double delta_c = a0 * a0 / (2.0 * std::cbrt(6.0) * s.radius);  // eq 3
  const double delta_f =
      delta_c * 2.0 * std::cbrt(6.0) * (2.0 / 3.0 * std::pow(4.0, -1.0 / 6.0) - std::pow(4.0, -2.0 / 3.0));
  for (auto [rule, expected] :
       {std::pair{JkrSeparation::displacement, delta_c}, std::pair{JkrSeparation::force, delta_f}}) {
    // At equilibrium, then leaving fast enough to escape: record the last overlap still in contact.
    SimulationSettings settings;
    settings.speed_scale = 0.5;
    Simulation sim = sphere_above_wall(-a0 * a0 / (3.0 * s.radius), 0.0, jkr_only(rule), settings);
    sim.particles().velocity[0].z = 0.5;
    double last_in_contact = 0.0;
    while (sim.contacts().size() > 0 && sim.step_count() < 100000) {
      last_in_contact = overlap_of(sim);
      sim.step();
    }
    REQUIRE(sim.contacts().size() == 0);
    // One step moves the sphere by about v dt: the break is detected within one step past it.
    const double travel = 0.5 * sim.time_step();
    CHECK(last_in_contact >= -expected);
    CHECK(last_in_contact < -expected + 2.0 * travel);
  }
}
