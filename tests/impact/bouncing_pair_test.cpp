// The fates-fixed rule (docs/IMPACT.md section 4) on two primaries that come down to a wall without
// adhesion, each bouncing off it: each one's path holds every course it can take (straight down to
// the wall, then within a ball about its mean course that grows at the spread of its possible
// courses), so two bouncing primaries whose paths stay apart cannot meet, and their fates are fixed;
// two whose paths cross are not. The tail of a shattering at a wall without adhesion is made of such
// primaries. Checked against the run itself.
#include <catch2/catch.hpp>

#include "engine/core/units.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/fate_rule.hpp"
#include "engine/impact/fragments.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using aerobreak::testing::unit_mass_density;
using aerobreak::testing::wall_contacts_of;

namespace {

// A dimer (the largest fragment) rising from a wall without adhesion, and two primaries 1.5 d above
// the wall and 2 `half_gap` apart along it, coming down at 0.01 d/tau and moving along the wall at
// `along` each, away from each other if `along` > 0. JKR, Mindlin friction mu = 0.3.
Simulation bouncing_pair(double half_gap, double along) {
  Particles p;
  for (const Vec3& x :
       {Vec3{0.0, 20.0, 20.0}, Vec3{0.982, 20.0, 20.0}, Vec3{-half_gap, 0.0, 2.0}, Vec3{half_gap, 0.0, 2.0}})
    p.add(x, 0.5, unit_mass_density);
  p.velocity = {{0.0, 0.0, 0.05}, {0.0, 0.0, 0.05}, {-along, 0.0, -0.01}, {along, 0.0, -0.01}};
  return Simulation(std::move(p), {reduced_material(0.001, 0.3)}, {testing::flat_wall(false)},
                    testing::jkr_with_friction());
}

// Runs for `time`; whether primaries 2 and 3 touched the wall and whether they touched each other.
struct Run {
  bool touched_wall[2] = {false, false};
  bool met = false;
};

Run run_for(Simulation& sim, double time) {
  Run r;
  const auto steps = static_cast<std::int64_t>(1.0 / sim.time_step()) + 1;
  while (sim.time() < time) {
    sim.run(steps);
    for (int k = 0; k < 2; ++k) r.touched_wall[k] = r.touched_wall[k] || wall_contacts_of(sim, 2 + k) > 0;
    sim.contacts().for_each([&](const ContactState& c) { r.met = r.met || (!c.with_wall && c.i >= 2 && c.j >= 2); });
  }
  return r;
}

}  // namespace

TEST_CASE("two primaries bouncing off a wall without adhesion on courses that stay apart have their fates fixed") {
  Simulation sim = bouncing_pair(3.0, 0.02);
  sim.run(1);
  const FatesJudgement judged = judge_fates(sim, {}, sim.time());
  CHECK(judged.reason.empty());  // refused as "can still meet" when two bouncing primaries were never trusted
  const std::vector<Fragment>& fragments = judged.fragments.fragments;
  REQUIRE(fragments.size() == 3);
  CHECK(fragments[1].bouncing);
  CHECK(fragments[2].bouncing);

  const Run run = run_for(sim, 400.0);
  CHECK(run.touched_wall[0]);
  CHECK(run.touched_wall[1]);
  CHECK_FALSE(run.met);
  CHECK(find_fragments(sim).fragments.size() == 3);
}

TEST_CASE("two primaries bouncing off a wall without adhesion towards each other can still meet, and do") {
  Simulation sim = bouncing_pair(3.0, -0.02);
  sim.run(1);
  CHECK_THAT(judge_fates(sim, {}, sim.time()).reason, Catch::Matchers::Contains("can still meet"));
  CHECK(run_for(sim, 400.0).met);
}
