// The landing fate of the fates-fixed rule (docs/IMPACT.md section 4) on a primary that glides
// towards an adhesive wall: its motion along the wall carries far more kinetic energy than the
// adhesion loop, its motion towards the wall less. Friction and rolling resistance act along the
// wall, so the normal motion meets the JKR loop as in a head-on impact at v_n: the primary is
// captured below the sticking speed (2 E_loop / m)^(1/2) whatever its speed along the wall, and
// leaves above it. The rule is checked against the run itself.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/core/units.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/fate_rule.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using aerobreak::testing::unit_mass_density;
using aerobreak::testing::wall_contacts_of;

namespace {
const double glide = 0.05;  // speed along the wall (d/tau)

// Primary 0 sits on an adhesive wall (a small overlap: in contact from the start); primary 1 glides away from it, 1.5 d
// above the wall, coming down at `normal_speed`. JKR without damping, Mindlin friction and rolling resistance on.
Simulation gliding_primary(double normal_speed) {
  Particles p;
  p.add({0.0, 0.0, 0.495}, 0.5, unit_mass_density);
  p.add({20.0, 0.0, 2.0}, 0.5, unit_mass_density);
  p.velocity[1] = {glide, 0.0, -normal_speed};
  ContactModelSpec model = testing::jkr_with_friction();
  model.rolling = true;
  model.critical_rolling = 0.02;
  return Simulation(std::move(p), {reduced_material(0.001, 0.3)}, {testing::flat_wall(true)}, model);
}

double sticking_speed(const Simulation& sim) {
  return std::sqrt(2.0 * sim.wall_loop_energy(1, 0) / sim.particles().mass[1]);
}

// Runs until primary 1 has touched the wall and for as long again, the wall contacts of primary 1
// counted at the end; the height its centre reached after touching is the largest seen.
struct Landing {
  bool touched = false;
  double highest_after = 0.0;
  std::size_t contacts_at_end = 0;
};

Landing run_past_landing(Simulation& sim, double normal_speed) {
  Landing l;
  const double arrival = 1.5 / normal_speed;
  const auto steps = static_cast<std::int64_t>(arrival / 100.0 / sim.time_step()) + 1;
  while (sim.time() < 2.0 * arrival) {
    sim.run(steps);
    if (wall_contacts_of(sim, 1) > 0) l.touched = true;
    if (l.touched) l.highest_after = std::max(l.highest_after, sim.particles().position[1].z);
  }
  l.contacts_at_end = wall_contacts_of(sim, 1);
  return l;
}

}  // namespace

TEST_CASE("a primary gliding down to an adhesive wall slower than the sticking speed lands and stays") {
  Simulation sim = gliding_primary(0.0);
  const double v_stick = sticking_speed(sim);
  const double normal_speed = 0.5 * v_stick;
  sim = gliding_primary(normal_speed);
  sim.run(1);
  const double kinetic = 0.5 * sim.particles().mass[1] * glide * glide;
  INFO("v_stick = " << v_stick << ", kinetic energy along the wall " << kinetic << " against the loop's "
                    << sim.wall_loop_energy(1, 0));
  REQUIRE(kinetic > 10.0 * sim.wall_loop_energy(1, 0));  // the old test by total energy refused it

  const FatesJudgement judged = judge_fates(sim, {}, sim.time());
  CHECK(judged.reason.empty());
  const std::vector<Fragment>& fragments = judged.fragments.fragments;
  REQUIRE(fragments.size() == 2);
  CHECK(fragments[1].first_primary == 1);
  CHECK(fragments[1].landing);

  const Landing landing = run_past_landing(sim, normal_speed);
  CHECK(landing.touched);
  CHECK(landing.contacts_at_end == 1);
  CHECK(landing.highest_after < 0.6);  // held: its centre stays within the loop's reach, delta_b << 0.1 d
  CHECK(sim.particles().position[1].x > 20.0 + glide * 1.5 / normal_speed * 0.5);  // it went on along the wall
}

TEST_CASE(
    "a primary gliding down to an adhesive wall faster than the sticking speed is not judged landing, and leaves") {
  const double normal_speed = 2.0 * sticking_speed(gliding_primary(0.0));
  Simulation sim = gliding_primary(normal_speed);
  sim.run(1);
  const FatesJudgement judged = judge_fates(sim, {}, sim.time());
  CHECK_THAT(judged.reason, Catch::Matchers::Contains("on its way back to the wall"));

  const Landing landing = run_past_landing(sim, normal_speed);
  CHECK(landing.touched);
  CHECK(landing.contacts_at_end == 0);
  CHECK(landing.highest_after > 1.0);
}
