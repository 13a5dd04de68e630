// Mindlin tangential spring with Coulomb slip (report eqs 10, 11, 13, 14): the law on its own
// (stiffness, limit, friction energy, history in the tangent plane), then a sphere resting on an
// adhesive wall that is set moving along it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/contact/normal_hertz.hpp"
#include "engine/contact/normal_jkr.hpp"
#include "engine/contact/tangential_mindlin.hpp"
#include "law_support.hpp"

using namespace aerobreak;
using namespace aerobreak::laws;

namespace {

const Vec3 up{0.0, 0.0, 1.0};

struct Evaluation {
  Vec3 force;
  Vec3 stretch;
  double energy = 0.0;
  DissipationTally tally;
};

// One call of the law with the given history, slip displacement (slip velocity x dt with dt = 1)
// and contact state.
Evaluation evaluate(double friction, Vec3 stretch, const Vec3& slip, const Vec3& normal, double radius,
                    double previous_radius, double coulomb_load, const ContactConstants& c) {
  Evaluation out;
  const SpringContext context{normal, 1.0, radius, previous_radius, coulomb_load};
  out.force = MindlinTangential{friction}.force(stretch, slip, context, c, out.tally);
  out.energy = MindlinTangential::energy(stretch, radius, c);
  out.stretch = stretch;
  return out;
}

}  // namespace

// Eq 11: k_t = 2G/(2-nu) sqrt(d delta) for identical spheres of diameter d. The law uses
// k_t = 8 G* a with G* = [(2-nu_i)/G_i + (2-nu_j)/G_j]^-1 = G / (2 (2-nu)) and a = sqrt(R* delta),
// R* = d/4: the same number, to round-off.
TEST_CASE("Mindlin stiffness 8 Geff a equals eq 11 for identical spheres") {
  for (double nu : {0.1, 0.3, 0.45})
    for (double radius : {0.5, 2.0})
      for (double overlap : {1e-4, 1e-2}) {
        INFO("nu = " << nu << ", R = " << radius << ", delta = " << overlap);
        const Material m = reduced_material(0.0, nu);
        const ContactConstants c = contact_constants(HertzNormal{}, m, m, radius, radius);
        CHECK(c.shear == Approx(m.shear_modulus() / (2.0 * (2.0 - nu))).epsilon(1e-14));
        const double a = HertzNormal{}.respond(overlap, c).contact_radius;
        const Vec3 slip{3e-7, -2e-7, 0.0};
        const Evaluation e = evaluate(1.0, {}, slip, up, a, a, 1e9, c);
        const double eq11 = 2.0 * m.shear_modulus() / (2.0 - nu) * std::sqrt(2.0 * radius * overlap);
        CHECK(-e.force.x / slip.x == Approx(eq11).epsilon(1e-12));
        CHECK(-e.force.y / slip.y == Approx(eq11).epsilon(1e-12));
        CHECK(e.force.z == 0.0);
        CHECK(e.energy == Approx(0.5 * eq11 * norm2(slip)).epsilon(1e-12));
        CHECK(e.tally.friction == 0.0);
      }
}

// Eq 14: |F_t| <= mu (F_n + 2 F_c). The JKR law hands over F_n + 2 F_c as the Coulomb load; once
// the trial stretch exceeds the limit the force sits on it, opposite to the trial stretch.
TEST_CASE("Coulomb limit mu (F_n + 2 F_c) caps the Mindlin force") {
  const Material m = reduced_material(1e-4, 0.3);
  const JkrNormal jkr;
  const ContactConstants c = contact_constants(jkr, m, m);
  const double mu = 0.3;
  const double equilibrium = c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius);
  for (double overlap : {equilibrium, 3.0 * equilibrium, -0.5 * c.critical_overlap}) {
    INFO("delta / delta_eq = " << overlap / equilibrium);
    const NormalResponse n = jkr.respond(overlap, c);
    CHECK(n.coulomb_load == Approx(n.force + 2.0 * c.pull_off_force).epsilon(1e-12));
    const double limit = mu * n.coulomb_load;
    const double k = 8.0 * c.shear * n.contact_radius;

    // Below the limit: a plain spring, nothing dissipated.
    const Vec3 start{0.25 * limit / k, 0.0, 0.0};
    const Evaluation elastic =
        evaluate(mu, start, {0.0, 0.2 * limit / k, 0.0}, up, n.contact_radius, n.contact_radius, n.coulomb_load, c);
    CHECK(elastic.force.x == Approx(-0.25 * limit).epsilon(1e-12));
    CHECK(elastic.force.y == Approx(-0.2 * limit).epsilon(1e-12));
    CHECK(elastic.tally.friction == 0.0);

    // Beyond it: capped.
    const Vec3 slip{1.5 * limit / k, 2.0 * limit / k, 0.0};
    const Vec3 trial = start + slip;
    const Evaluation capped = evaluate(mu, start, slip, up, n.contact_radius, n.contact_radius, n.coulomb_load, c);
    CHECK(norm(capped.force) == Approx(limit).epsilon(1e-12));
    CHECK(norm(cross(capped.force, trial)) < 1e-12 * limit * norm(trial));
    CHECK(dot(capped.force, trial) < 0.0);
    CHECK(k * norm(capped.stretch) == Approx(limit).epsilon(1e-12));
    CHECK(capped.energy == Approx(0.5 * k * norm2(capped.stretch)).epsilon(1e-12));
  }
}

// The friction channel receives the energy balance of a step: the work of the spring force along
// the stretch increment s_inc (trapezoidal in the force, as velocity Verlet applies it) minus the
// change of the stored energy, D = k_t/2 [(s_old + s_new).s_inc + |s_old|^2 - |s_new|^2]. It follows
// that 0 <= D <= mu F |s_inc| (|s_old|, |s_new| <= mu F / k_t), with D = mu F |s_inc| exactly
// while the contact slides steadily at its limit, and D = 0 for mu = 0 (no force, no work).
TEST_CASE("the friction channel receives the work of the capped Mindlin force minus the stored-energy change") {
  const Material m = reduced_material(1e-4, 0.3);
  const ContactConstants c = contact_constants(JkrNormal{}, m, m);
  const NormalResponse n = JkrNormal{}.respond(c.equilibrium_radius * c.equilibrium_radius / c.radius, c);
  const double a = n.contact_radius;
  const double k = 8.0 * c.shear * a;
  const double mu = 0.5;
  const double limit = mu * n.coulomb_load;
  const double length = limit / k;  // |s| at the limit

  // Steady sliding: the spring sits on the limit and the slip continues along it.
  const Vec3 along{0.6, 0.8, 0.0};
  const Vec3 slip = 0.01 * length * along;
  const Evaluation steady = evaluate(mu, length * along, slip, up, a, a, n.coulomb_load, c);
  CHECK(steady.tally.friction == Approx(limit * norm(slip)).epsilon(1e-12));

  // Without friction there is no force, so nothing is dissipated whatever the slip.
  const Evaluation frictionless = evaluate(0.0, {}, slip, up, a, a, n.coulomb_load, c);
  CHECK(frictionless.force == Vec3{});
  CHECK(frictionless.tally.friction == 0.0);

  // Any capped step: the balance, and its bounds.
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    Vec3 start{uniform(random), uniform(random), 0.0};
    start *= length * std::fabs(uniform(random)) / norm(start);
    const Vec3 increment = 3.0 * length * Vec3{uniform(random), uniform(random), 0.0};
    const Evaluation e = evaluate(mu, start, increment, up, a, a, n.coulomb_load, c);
    INFO("trial " << trial);
    const double work = 0.5 * k * dot(start + e.stretch, increment);
    const double stored = 0.5 * k * (norm2(e.stretch) - norm2(start));
    CHECK(e.tally.friction == Approx(work - stored).margin(1e-14 * limit * length));
    CHECK(e.tally.friction >= -1e-14 * limit * length);
    CHECK(e.tally.friction <= limit * norm(increment) * (1.0 + 1e-12));
  }
}

// The history is carried into the current tangent plane by a rotation: its length (the stored
// energy) is kept and it lies in the new plane, along the projection of the old stretch.
TEST_CASE("Mindlin stretch is rotated into the new tangent plane with its length kept") {
  const Material m = reduced_material(0.0, 0.3);
  const ContactConstants c = contact_constants(HertzNormal{}, m, m);
  const double a = HertzNormal{}.respond(1e-3, c).contact_radius;
  const Vec3 old_stretch{1e-4, 5e-5, 0.0};
  const double tilt = 0.3;
  const Vec3 normal{std::sin(tilt), 0.0, std::cos(tilt)};
  const Evaluation e = evaluate(1.0, old_stretch, {}, normal, a, a, 1e9, c);
  CHECK(norm(e.stretch) == Approx(norm(old_stretch)).epsilon(1e-14));
  CHECK(std::fabs(dot(e.stretch, normal)) < 1e-15 * norm(old_stretch));
  const Vec3 projection = old_stretch - dot(old_stretch, normal) * normal;
  CHECK(norm(cross(e.stretch, projection)) < 1e-14 * norm2(old_stretch));
  CHECK(dot(e.stretch, projection) > 0.0);
  CHECK(norm(e.force) == Approx(8.0 * c.shear * a * norm(old_stretch)).epsilon(1e-14));
  CHECK(e.tally.friction == 0.0);
  CHECK(e.tally.stiffness_work == 0.0);

  // A contact radius that changed since the last step changes the stiffness at fixed stretch:
  // the work 0.5 (k_t - k_t,previous) |s|^2 is booked as stiffness work.
  const Evaluation grown = evaluate(1.0, old_stretch, {}, up, a, 0.9 * a, 1e9, c);
  CHECK(grown.tally.stiffness_work == Approx(0.5 * 8.0 * c.shear * 0.1 * a * norm2(old_stretch)).epsilon(1e-12));
}

namespace {

// A unit sphere just touching an adhesive JKR wall, with visco-elastic damping to take out the
// adhesive approach.
Simulation sphere_on_wall(double friction) {
  ContactModelSpec spec;
  spec.normal = NormalLaw::jkr;
  spec.damping = DampingLaw::viscoelastic;
  spec.dissipative_time = 1.0;
  spec.friction = friction;
  return sphere_over_floor(spec, reduced_material(1e-4, 0.3), -1e-6, {}, true);
}

// Lets the sphere settle at its equilibrium overlap, then sets it moving along x at v0.
void settle_and_launch(Simulation& sim, double v0) {
  sim.run(3000);
  REQUIRE(sim.contacts().size() == 1);
  REQUIRE(std::fabs(sim.particles().velocity[0].z) < 1e-12);
  sim.particles().velocity[0].x = v0;
}

}  // namespace

// With mu = 10 the contact point sticks (the spring force stays far below the limit), so the only
// horizontal force acts at the contact point. The angular momentum about it,
// L = I w_y + m (R - delta) v_x, is then conserved exactly by the integrator (the kick changes of
// I w and m (R - delta) v cancel), and the sphere settles into rolling at
// v = v0 / (1 + I / (m (R - delta)^2)) (~5/7 v0), about which the undamped tangential spring
// oscillates: its mean over ~90 oscillations is checked to 0.5 % (measured 0.05 %).
TEST_CASE("a sphere set moving on an adhesive wall with high friction sticks and rolls") {
  const double v0 = 1e-3;
  Simulation sim = sphere_on_wall(10.0);
  settle_and_launch(sim, v0);
  const Particles& p = sim.particles();
  const auto momentum = [&] {
    return p.inertia[0] * p.angular_velocity[0].y + p.mass[0] * p.position[0].z * p.velocity[0].x;
  };
  const double l0 = momentum();
  double mean = 0.0;
  double drift = 0.0;
  const int steps = 6000;
  for (int s = 0; s < steps; ++s) {
    sim.step();
    mean += p.velocity[0].x / steps;
    drift = std::max(drift, std::fabs(momentum() - l0));
  }
  CHECK(drift < 1e-12 * l0);
  const double lever = p.position[0].z;
  const double rolling = v0 / (1.0 + p.inertia[0] / (p.mass[0] * lever * lever));
  CHECK(mean == Approx(rolling).epsilon(5e-3));
  CHECK(sim.energy().dissipation.friction == 0.0);
}

// mu = 0: the Coulomb limit is zero, so there is no tangential force at all and the sphere keeps
// its velocity and does not spin, exactly.
TEST_CASE("a sphere set moving on an adhesive wall without friction slides at constant velocity") {
  const double v0 = 1e-3;
  Simulation sim = sphere_on_wall(0.0);
  settle_and_launch(sim, v0);
  for (int s = 0; s < 2000; ++s) {
    sim.step();
    REQUIRE(sim.particles().velocity[0].x == v0);
    REQUIRE(sim.particles().angular_velocity[0] == Vec3{});
  }
}

// Same slide, energy budget: no force does work, so nothing may be booked as friction and the
// balance must stay put (tolerance: 1e-3 of the sphere's kinetic energy; the settled normal
// contact moves it by far less).
TEST_CASE("a frictionless slide books no energy in the friction channel") {
  const double v0 = 1e-3;
  Simulation sim = sphere_on_wall(0.0);
  settle_and_launch(sim, v0);
  const EnergyBudget before = sim.energy();
  const double kinetic = 0.5 * sim.particles().mass[0] * v0 * v0;
  sim.run(6000);
  const EnergyBudget after = sim.energy();
  CHECK(after.dissipation.friction - before.dissipation.friction < 1e-3 * kinetic);
  CHECK(after.balance() == Approx(before.balance()).margin(1e-3 * kinetic));
}

// With little friction (mu = 0.05, limit ~ mu 2 F_c) a fast sphere slides first: the friction
// decelerates it and spins it up until its contact point sticks, at v = v0 / (1 + I/(m (R-delta)^2))
// (~5/7 v0, angular momentum about the contact point conserved as above), about which the
// tangential spring then oscillates (mean over ~90 oscillations: within 0.5 %). The kinetic energy
// it loses on the way, m v0^2 / 2 (1 - v/v0), goes to the friction channel, less the small part the
// undamped tangential spring still holds (hence 2e-3); the balance, which counts the spring, must
// hold to 1e-3 of the loss, far above the integration error of the ~520 sliding steps.
TEST_CASE("a sphere sliding on a wall with friction comes to rolling and the friction channel holds the energy lost") {
  const double v0 = 1e-2;
  Simulation sim = sphere_on_wall(0.05);
  settle_and_launch(sim, v0);
  const Particles& p = sim.particles();
  const EnergyBudget before = sim.energy();
  sim.run(1500);  // sliding ends after ~520 steps
  const double lever = p.position[0].z;
  const double rolling = v0 / (1.0 + p.inertia[0] / (p.mass[0] * lever * lever));
  const double lost = 0.5 * p.mass[0] * v0 * v0 * (1.0 - rolling / v0);
  const EnergyBudget after = sim.energy();
  double mean = 0.0;
  const int steps = 6000;
  for (int s = 0; s < steps; ++s) {
    sim.step();
    mean += p.velocity[0].x / steps;
  }
  CHECK(mean == Approx(rolling).epsilon(5e-3));
  CHECK(after.dissipation.friction - before.dissipation.friction == Approx(lost).epsilon(2e-3));
  CHECK(after.balance() == Approx(before.balance()).margin(1e-3 * lost));
}
