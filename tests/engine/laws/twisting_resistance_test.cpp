// Twisting resistance (report section 2.2, eq 17, after Marshall 2009) at the level of one
// contact: torsion spring k_tw = k_t a^2 / 2 = 4 G* a^3 about the normal, slip limit
// (2/3) mu a (F_n + 2 F_c), direction and energy.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/contact/normal_jkr.hpp"
#include "engine/contact/twisting_resistance.hpp"
#include "law_support.hpp"

using namespace aerobreak;
using namespace aerobreak::laws;

namespace {

const Material material = reduced_material(1e-4, 0.3);

struct Evaluation {
  Vec3 torque;
  double energy = 0.0;
  DissipationTally tally;
};

Evaluation twist(double friction, double& angle, const Vec3& relative_spin, const Vec3& normal, double a,
                 double previous_a, double coulomb_load, const ContactConstants& c) {
  Evaluation out;
  const SpringContext context{normal, 1.0, a, previous_a, coulomb_load};  // dt = 1
  out.torque = TwistingResistance{friction}.torque(angle, relative_spin, context, c, out.tally);
  out.energy = TwistingResistance::energy(angle, a, c);
  return out;
}

}  // namespace

// A relative spin w about n for one step twists the contact by phi = w dt; the torque on i is
// -k_tw phi n with k_tw = k_t a^2 / 2 (the Mindlin stiffness k_t = 8 G* a spread over the contact
// disk), i.e. 4 G* a^3. Spin about tangential axes does not twist.
TEST_CASE("twisting torque is -k_tw phi n with k_tw = k_t a^2 / 2 = 4 Geff a^3") {
  const ContactConstants c = contact_constants(JkrNormal{}, material, material);
  const Vec3 normal = Vec3{1.0, 2.0, 2.0} / 3.0;
  for (double x : {0.7, 1.0, 2.0}) {
    INFO("a / a0 = " << x);
    const double a = x * c.equilibrium_radius;
    const double k_t = 8.0 * c.shear * a;
    const double k_tw = 0.5 * k_t * a * a;
    CHECK(k_tw == Approx(4.0 * c.shear * a * a * a).epsilon(1e-14));
    const double w = 3e-7;
    const Vec3 spin = w * normal + Vec3{2.0, -1.0, 0.0} * 1e-6;  // (2, -1, 0) is normal to n
    double angle = 0.0;
    const Evaluation e = twist(0.5, angle, spin, normal, a, a, 1.0, c);
    CHECK(angle == Approx(w).epsilon(1e-12));
    const Vec3 expected = -k_tw * w * normal;
    CHECK(norm(e.torque - expected) < 1e-12 * norm(expected));
    CHECK(dot(e.torque, spin) < 0.0);
    CHECK(e.energy == Approx(0.5 * k_tw * w * w).epsilon(1e-12));
    CHECK(e.tally.twisting == 0.0);

    // Spinning the other way reverses the torque.
    double reverse = 0.0;
    CHECK(norm(twist(0.5, reverse, -1.0 * spin, normal, a, a, 1.0, c).torque + e.torque) < 1e-15 * norm(expected));
  }
}

// Eq 17: |M_t| <= (2/3) mu a (F_n + 2 F_c). Beyond it the torque sits on the limit and the angle
// is held at limit / k_tw. The twisting channel receives the energy balance of the step, the work
// of the torque along the angle increment (trapezoidal) minus the change of the spring energy,
// (k_tw / 2) [(phi_old + phi_new) dphi + phi_old^2 - phi_new^2]; while the contact keeps twisting
// at its limit that is exactly |M_t| |w| dt.
TEST_CASE("twisting torque is capped at (2/3) mu a (F_n + 2 F_c) and the twisting channel gets the slip energy") {
  const ContactConstants c = contact_constants(JkrNormal{}, material, material);
  const Vec3 normal{0.0, 0.0, -1.0};
  const double mu = 0.4;
  const double equilibrium = c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius);
  for (double overlap : {equilibrium, 4.0 * equilibrium, -0.5 * c.critical_overlap}) {
    INFO("delta / delta_eq = " << overlap / equilibrium);
    const NormalResponse n = JkrNormal{}.respond(overlap, c);
    const double a = n.contact_radius;
    const double k_tw = 4.0 * c.shear * a * a * a;
    const double limit = 2.0 / 3.0 * mu * a * (n.force + 2.0 * c.pull_off_force);
    const double start = -0.5 * limit / k_tw;
    const double w = -2.0 * limit / k_tw;  // twists on in the same sense: trial 2.5 x the limit
    double angle = start;
    const Evaluation e = twist(mu, angle, w * normal, normal, a, a, n.coulomb_load, c);
    CHECK(norm(e.torque) == Approx(limit).epsilon(1e-12));
    CHECK(dot(e.torque, normal) > 0.0);  // opposes the twist, which is along -n
    CHECK(angle == Approx(-limit / k_tw).epsilon(1e-12));
    CHECK(e.tally.twisting ==
          Approx(0.5 * k_tw * ((start + angle) * w + start * start - angle * angle)).epsilon(1e-12));
    CHECK(e.energy == Approx(0.5 * k_tw * angle * angle).epsilon(1e-12));

    // Twisting on at the limit.
    const double small = 0.01 * w;
    const Evaluation on = twist(mu, angle, small * normal, normal, a, a, n.coulomb_load, c);
    CHECK(on.tally.twisting == Approx(limit * std::fabs(small)).epsilon(1e-12));
  }
}

// The angle is kept while the contact radius changes; the torsion spring's energy change at fixed
// angle, 0.5 (k_tw - k_tw,previous) phi^2, is booked as stiffness work.
TEST_CASE("twisting stiffness change at fixed angle is booked as stiffness work") {
  const ContactConstants c = contact_constants(JkrNormal{}, material, material);
  const double a = c.equilibrium_radius;
  const double previous = 0.8 * a;
  double angle = 1e-6;
  const Evaluation e = twist(1e6, angle, {}, {0.0, 0.0, 1.0}, a, previous, 1.0, c);
  const double k = 4.0 * c.shear * a * a * a;
  const double k_previous = 4.0 * c.shear * previous * previous * previous;
  CHECK(angle == 1e-6);
  CHECK(e.tally.stiffness_work == Approx(0.5 * (k - k_previous) * 1e-12).epsilon(1e-12));
  CHECK(e.torque.z == Approx(-k * 1e-6).epsilon(1e-14));
}
