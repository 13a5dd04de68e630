// Rolling resistance of sintered contacts (report section 2.2, eq 18, after Zhao & Marshall 2008
// and Marshall 2009) at the level of one contact: stiffness k_r = 4 F_c (a/a0)^(3/2), direction,
// saturation at k_r xi_crit and its energy, and no torque for a rigidly co-rotating pair.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/contact/contact_model.hpp"
#include "engine/contact/damping.hpp"
#include "engine/contact/normal_jkr.hpp"
#include "engine/contact/rolling_resistance.hpp"
#include "engine/contact/twisting_resistance.hpp"
#include "law_support.hpp"

using namespace aerobreak;
using namespace aerobreak::laws;

namespace {

const Vec3 up{0.0, 0.0, 1.0};
const Material material = reduced_material(1e-4, 0.3);

ContactConstants jkr_pair() { return contact_constants(JkrNormal{}, material, material); }

// Overlap at which the JKR contact radius is x a0 (eq 2).
double overlap_at(double x, const ContactConstants& c) {
  return jkr_overlap_ratio(x) * c.equilibrium_radius * c.equilibrium_radius / c.radius;
}

struct Evaluation {
  Vec3 torque;
  double energy = 0.0;
  DissipationTally tally;
};

Evaluation roll(const RollingResistance& law, Vec3& displacement, const Vec3& relative_spin, double a,
                const ContactConstants& c, double dt = 1.0) {
  Evaluation out;
  // The normal law hands on (a/a0)^(3/2); the last step's radius is this one's (a fixed).
  const double x = a / c.equilibrium_radius;
  const SpringContext context{up, dt, a, a, 0.0, x * std::sqrt(x)};
  out.torque = law.torque(displacement, relative_spin, context, c, out.tally);
  out.energy = RollingResistance::energy(displacement, a, c);
  return out;
}

}  // namespace

// One step of relative spin Omega from a relaxed spring: xi = -R* (Omega x n) dt, and the torque on
// i, M = k_r n x xi = -k_r R* dt Omega_t (Omega_t: the part of Omega in the tangent plane), opposes
// the relative rolling, with |M| = k_r |xi| and k_r = 4 F_c (a/a0)^(3/2) (eq 18).
TEST_CASE("rolling torque is k_r xi with k_r = 4 F_c (a/a0)^(3/2) and opposes the relative rolling") {
  const ContactConstants c = jkr_pair();
  const RollingResistance law{1.0};  // xi_crit far beyond the displacements used here
  const Vec3 spin_i{3e-6, -2e-6, 5e-6};
  const Vec3 spin_j{-1e-6, 1e-6, -4e-6};
  const Vec3 relative = spin_i - spin_j;
  const Vec3 tangential = relative - dot(relative, up) * up;
  for (double x : {0.8, 1.0, 1.5}) {
    INFO("a / a0 = " << x);
    const double a = JkrNormal{}.respond(overlap_at(x, c), c).contact_radius;
    REQUIRE(a == Approx(x * c.equilibrium_radius).epsilon(1e-9));
    const double k_r = 4.0 * c.pull_off_force * std::pow(a / c.equilibrium_radius, 1.5);
    Vec3 xi;
    const Evaluation e = roll(law, xi, relative, a, c);
    const Vec3 expected = -k_r * c.radius * tangential;
    CHECK(e.torque.x == Approx(expected.x).epsilon(1e-12));
    CHECK(e.torque.y == Approx(expected.y).epsilon(1e-12));
    CHECK(std::fabs(e.torque.z) < 1e-15 * norm(expected));
    CHECK(norm(e.torque) == Approx(k_r * norm(xi)).epsilon(1e-12));
    CHECK(dot(e.torque, relative) < 0.0);
    CHECK(e.energy == Approx(k_r * norm2(xi) / (2.0 * c.radius)).epsilon(1e-12));
    CHECK(e.tally.rolling == 0.0);

    // Reversing the relative rolling reverses the torque.
    Vec3 xi_j;
    const Evaluation mirrored = roll(law, xi_j, -1.0 * relative, a, c);
    CHECK(norm(mirrored.torque + e.torque) < 1e-15 * norm(e.torque));
  }
}

// Under a steady relative spin the torque grows linearly, k_r n R* |Omega| dt after n steps, until
// |xi| reaches xi_crit; from then on it stays at k_r xi_crit. The rolling channel receives the
// energy balance of each step, the work of the torque along the displacement increment D
// (trapezoidal) minus the change of the spring energy k_r |xi|^2 / (2R*):
// (k_r / 2R*) [(xi_old + xi_new).D + |xi_old|^2 - |xi_new|^2]. Once saturated that is exactly the
// work of the torque against the relative rolling, k_r xi_crit |Omega| dt, i.e. |M| |Omega_t| dt.
TEST_CASE("rolling torque saturates at k_r xi_crit and the rolling channel receives the slip energy") {
  const ContactConstants c = jkr_pair();
  const double a = c.equilibrium_radius;
  const double k_r = 4.0 * c.pull_off_force;  // a = a0
  const Vec3 spin{0.0, 2e-5, 0.0};
  const double step = c.radius * norm(spin);  // |D|, dt = 1
  const double critical = 10.5 * step;
  const RollingResistance law{critical};
  const double compliance = 1.0 / (2.0 * c.radius);
  Vec3 xi;
  for (int n = 1; n <= 20; ++n) {
    INFO("step " << n);
    const Vec3 before = xi;
    const Vec3 increment = -c.radius * cross(spin, up);
    const Evaluation e = roll(law, xi, spin, a, c);
    CHECK(dot(e.torque, spin) < 0.0);
    if (n <= 10) {
      CHECK(norm(e.torque) == Approx(k_r * n * step).epsilon(1e-12));
      CHECK(e.tally.rolling == 0.0);
      continue;
    }
    CHECK(norm(e.torque) == Approx(k_r * critical).epsilon(1e-12));
    CHECK(norm(xi) == Approx(critical).epsilon(1e-12));
    CHECK(e.energy == Approx(compliance * k_r * critical * critical).epsilon(1e-12));
    const double balance = compliance * k_r * (dot(before + xi, increment) + norm2(before) - norm2(xi));
    CHECK(e.tally.rolling == Approx(balance).epsilon(1e-12));
    if (n > 11) CHECK(e.tally.rolling == Approx(norm(e.torque) * norm(spin)).epsilon(1e-10));
  }
}

// In a contact, only the relative spin w_i - w_j rolls the contact: i turning at Omega against a
// still j, or j turning at -Omega against a still i, give the same torque on i, and j receives
// the opposite torque.
TEST_CASE("rolling torque on a pair depends only on the relative spin and acts oppositely on j") {
  using Model = ContactModel<JkrNormal, NoDamping, NoTangential, RollingResistance, NoTwisting>;
  const Model model{JkrNormal{}, NoDamping{}, NoTangential{}, RollingResistance{1e-3}, NoTwisting{}};
  const ContactConstants c = jkr_pair();
  const double overlap = overlap_at(1.2, c);
  const double lever = unit_radius - 0.5 * overlap;
  const Vec3 omega{4e-6, -3e-6, 0.0};
  const auto torques = [&](const Vec3& spin_i, const Vec3& spin_j) {
    ContactState state;
    state.constants = c;
    model.open(state, overlap);
    DissipationTally tally;
    return model.evaluate(state, {up, overlap, {}, spin_i, spin_j, lever, lever}, 0.1, tally);
  };
  const ContactLoad turning_i = torques(omega, {});
  const ContactLoad turning_j = torques({}, -1.0 * omega);
  CHECK(norm(turning_i.torque_i) > 0.0);
  CHECK(norm(turning_i.torque_i - turning_j.torque_i) < 1e-14 * norm(turning_i.torque_i));
  CHECK(norm(turning_i.torque_j + turning_i.torque_i) < 1e-14 * norm(turning_i.torque_i));
  CHECK(dot(turning_i.torque_i, omega) < 0.0);
}

// A pair turning as one rigid body (w_i = w_j = Omega, v_i - v_j = Omega x (r_i - r_j)) deforms
// nothing: the contact point has no relative velocity, there is no relative rolling or twisting,
// so the tangential, rolling and twisting springs stay relaxed while the normal direction turns.
TEST_CASE("a rigidly co-rotating pair feels no tangential force and no rolling or twisting torque") {
  using Model = ContactModel<JkrNormal, NoDamping, MindlinTangential, RollingResistance, TwistingResistance>;
  const Model model{JkrNormal{}, NoDamping{}, MindlinTangential{0.5}, RollingResistance{1e-3}, TwistingResistance{0.5}};
  ContactState state;
  state.constants = jkr_pair();
  const double overlap = overlap_at(1.0, state.constants);
  model.open(state, overlap);
  const double distance = 2.0 * unit_radius - overlap;
  const Vec3 omega{2e-3, -1e-3, 3e-3};
  const double rate = norm(omega);
  const Vec3 axis = omega / rate;
  const Vec3 n0{1.0, 0.0, 0.0};
  const double dt = 0.1;
  DissipationTally tally;
  for (int s = 0; s < 200; ++s) {
    // Rodrigues: n0 turned by rate t about axis.
    const double angle = rate * dt * s;
    const Vec3 n =
        std::cos(angle) * n0 + std::sin(angle) * cross(axis, n0) + (1.0 - std::cos(angle)) * dot(axis, n0) * axis;
    const ContactMotion motion{n,
                               overlap,
                               cross(omega, -distance * n),
                               omega,
                               omega,
                               unit_radius - 0.5 * overlap,
                               unit_radius - 0.5 * overlap};
    const ContactLoad load = model.evaluate(state, motion, dt, tally);
    const Vec3 tangential_force = load.force_i - dot(load.force_i, n) * n;
    CHECK(norm(tangential_force) < 1e-12 * state.constants.pull_off_force);
    CHECK(norm(load.torque_i) < 1e-16);
    CHECK(norm(load.torque_j) < 1e-16);
  }
  CHECK(norm(state.rolling_displacement) == 0.0);
  CHECK(state.twist_angle == 0.0);
  CHECK(norm(state.tangential_stretch) < 1e-15);
  CHECK(tally.rolling == 0.0);
  CHECK(tally.twisting == 0.0);
  CHECK(tally.friction == 0.0);
}

// k_r follows the contact radius: when a grows from the last step's a_prev at fixed xi, the work
// done on the spring is (k_r(a) - k_r(a_prev)) |xi|^2 / (2 R*), booked as stiffness work.
TEST_CASE("a growing contact radius books the rolling spring's stiffness change as stiffness work") {
  const ContactConstants c = jkr_pair();
  const RollingResistance law{1.0};
  const double a_prev = c.equilibrium_radius, a = 1.3 * c.equilibrium_radius;
  const double x = a / c.equilibrium_radius;
  const SpringContext context{up, 1.0, a, a_prev, 0.0, x * std::sqrt(x)};
  Vec3 xi{2e-3, -1e-3, 0.0};
  const double held = norm2(xi);
  DissipationTally tally;
  law.torque(xi, Vec3{}, context, c, tally);  // no relative spin: xi is held
  const double k = 4.0 * c.pull_off_force * std::pow(1.3, 1.5);
  const double k_previous = 4.0 * c.pull_off_force;
  CHECK(norm2(xi) == Approx(held).epsilon(1e-15));
  CHECK(tally.stiffness_work == Approx((k - k_previous) * held / (2.0 * c.radius)).epsilon(1e-12));
}

TEST_CASE("without adhesion the rolling spring has no stiffness and exerts no torque") {
  ContactConstants c = jkr_pair();
  c.pull_off_force = 0.0;
  c.equilibrium_radius = 0.0;
  const double a = 0.05 * c.radius;
  const SpringContext context{up, 1.0, a, a, 0.0, 0.0};
  Vec3 xi{1e-3, 0.0, 0.0};
  DissipationTally tally;
  const Vec3 torque = RollingResistance{0.01}.torque(xi, Vec3{0.0, 1e-3, 0.0}, context, c, tally);
  CHECK(RollingResistance::rolling_stiffness(a, c) == 0.0);
  CHECK(norm(torque) == 0.0);
  CHECK(tally.stiffness_work == 0.0);
  CHECK(RollingResistance::energy(xi, a, c) == 0.0);
}
