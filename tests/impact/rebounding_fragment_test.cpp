// The fates-fixed rule (docs/IMPACT.md section 4) on a fragment of several primaries that comes back
// to a wall without adhesion: with less energy in the wall's frame (kinetic and stored above rest)
// than its weakest bond's break energy it cannot break, whatever it meets at the wall, and it cannot
// stay there: its fate is fixed, and its path is the one of that energy (a ball about where it can
// first touch the wall, growing at the fastest its centre can then move). A dimer coming down slowly
// and one tumbling just above the wall are judged so and checked against the run; a dimer with more
// energy than its bond's is not judged so.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/core/units.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/fate_rule.hpp"
#include "engine/impact/fragments.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using aerobreak::testing::unit_mass_density;

namespace {

// A straight trimer (the largest fragment) rising at 0.05 d/tau far from the wall, and a dimer lying
// along x with its centre `height` above a wall without adhesion, moving at `normal_speed` along the
// wall's normal and turning end over end (about y) at `orbit` d/tau relative speed of its primaries.
// JKR with visco-elastic damping, Mindlin friction, rolling resistance, gamma/k_n = 0.001.
Simulation dimer_near_wall(double height, double normal_speed, double orbit) {
  Particles p;
  for (int k = 0; k < 3; ++k) p.add({40.0 + 0.982 * k, 0.0, 20.0}, 0.5, unit_mass_density);
  p.add({-0.491, 0.0, height}, 0.5, unit_mass_density);
  p.add({0.491, 0.0, height}, 0.5, unit_mass_density);
  p.velocity = {{0.0, 0.0, 0.05},
                {0.0, 0.0, 0.05},
                {0.0, 0.0, 0.05},
                {0.0, 0.0, normal_speed + 0.5 * orbit},
                {0.0, 0.0, normal_speed - 0.5 * orbit}};
  p.angular_velocity[3] = p.angular_velocity[4] = {0.0, orbit / 0.982, 0.0};  // spinning with the turn
  ContactModelSpec model = testing::jkr_with_friction();
  model.damping = DampingLaw::viscoelastic;
  model.dissipative_time = 0.05;
  model.rolling = true;
  model.critical_rolling = 0.02;
  return Simulation(std::move(p), {reduced_material(0.001, 0.3)}, {testing::flat_wall(false)}, model);
}

bool dimer_touches_wall(const Simulation& sim) {
  bool touches = false;
  sim.contacts().for_each([&](const ContactState& c) { touches = touches || (c.with_wall && c.i >= 3); });
  return touches;
}

// Runs for `time`; whether the dimer touched the wall, and the fragments at the end.
struct Run {
  bool touched = false;
  std::size_t fragments = 0;
  double dimer_speed_at_end = 0.0;
};

Run run_for(Simulation& sim, double time) {
  Run r;
  const auto steps = static_cast<std::int64_t>(0.5 / sim.time_step()) + 1;
  while (sim.time() < time) {
    sim.run(steps);
    r.touched = r.touched || dimer_touches_wall(sim);
  }
  const FragmentAnalysis fa = find_fragments(sim);
  r.fragments = fa.fragments.size();
  r.dimer_speed_at_end = norm(fa.fragments[fa.fragment_of[3]].velocity);
  return r;
}

}  // namespace

TEST_CASE("a dimer coming down slowly to a wall without adhesion has its fate fixed, and leaves it whole") {
  Simulation sim = dimer_near_wall(2.0, -0.005, 0.0);
  sim.run(1);
  const FatesJudgement judged = judge_fates(sim, {}, sim.time());
  CHECK(judged.reason.empty());  // "on its way back to the wall" when only a primary alone could bounce
  REQUIRE(judged.fragments.fragments.size() == 2);
  CHECK(judged.fragments.fragments[1].bouncing);

  const Run run = run_for(sim, 1000.0);
  CHECK(run.touched);
  CHECK(run.fragments == 2);
  const double energy = 0.5 * 2.0 * 0.005 * 0.005;  // its kinetic energy now: what bounds its speed after
  CHECK(run.dimer_speed_at_end <= std::sqrt(2.0 * energy / 2.0) * (1.0 + 1e-9));
}

TEST_CASE("a dimer tumbling just above a wall without adhesion has its fate fixed, and stays whole") {
  Simulation sim = dimer_near_wall(0.55, 0.001, 0.008);
  sim.run(1);
  const FatesJudgement judged = judge_fates(sim, {}, sim.time());
  CHECK(judged.reason.empty());  // "may still swing back to it" before
  REQUIRE(judged.fragments.fragments.size() == 2);
  CHECK(judged.fragments.fragments[1].bouncing);

  const Run run = run_for(sim, 1000.0);
  CHECK(run.touched);  // it did swing back
  CHECK(run.fragments == 2);
}

TEST_CASE("a dimer coming down to a wall without adhesion with more energy than its bond's is not judged so") {
  Simulation sim = dimer_near_wall(2.0, -0.02, 0.0);  // 4e-4 k_n d^2, nine times its bond's 4.46e-5
  sim.run(1);
  CHECK_THAT(judge_fates(sim, {}, sim.time()).reason, Catch::Matchers::Contains("on its way back to the wall"));
}
