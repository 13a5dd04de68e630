// The clear fate of the fates-fixed rule (docs/IMPACT.md section 4) on a spinning dimer in flight: as
// its bond opens, the pair's orbit widens and, at fixed angular momentum, its rotation gives up
// energy to the opening. A dimer whose relative motion and stored energy alone are below the bond's
// break energy can still come apart by that; the rule must count it, and the run decides. Scanned
// from 0.03 to 0.115 d/tau of orbit speed at this opening, the dimer comes apart from 0.050 on; the
// rule without the rotation's unwinding judged it clear up to 0.060, with it up to 0.030 only.
#include <catch2/catch.hpp>

#include "engine/core/units.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/fate_rule.hpp"
#include "engine/impact/fragments.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using aerobreak::testing::unit_mass_density;

namespace {

// Two JKR primaries (gamma/k_n = 0.001, no damping) 0.982 d apart, far above a wall without
// adhesion and rising from it at 0.05 d/tau, turning about each other at `orbit` d/tau relative
// speed and opening at `opening`: the state of a dimer seen in a break-up on an adhesive wall.
Simulation spinning_dimer(double orbit, double opening) {
  Particles p;
  p.add({0.0, 0.0, 20.0}, 0.5, unit_mass_density);
  p.add({0.982, 0.0, 20.0}, 0.5, unit_mass_density);
  p.velocity = {{-0.5 * opening, -0.5 * orbit, 0.05}, {0.5 * opening, 0.5 * orbit, 0.05}};
  p.angular_velocity = {{0.0, 0.0, orbit / 0.982}, {0.0, 0.0, orbit / 0.982}};  // spinning with the orbit
  return Simulation(std::move(p), {reduced_material(0.001, 0.3)}, {testing::flat_wall(false)},
                    testing::jkr_with_friction());
}

std::size_t fragments_after(Simulation& sim, double time) {
  const auto steps = static_cast<std::int64_t>(time / sim.time_step()) + 1;
  sim.run(steps);
  return find_fragments(sim).fragments.size();
}

}  // namespace

TEST_CASE("a dimer turning fast enough to open its bond by its rotation is not judged clear, and comes apart") {
  Simulation sim = spinning_dimer(0.055, 0.0058);
  sim.run(1);
  REQUIRE(find_fragments(sim).fragments.size() == 1);
  CHECK_THAT(judge_fates(sim, {}, sim.time()).reason, Catch::Matchers::Contains("internal energy"));
  CHECK(fragments_after(sim, 500.0) == 2);
}

TEST_CASE("a dimer turning slowly is judged clear, and stays one") {
  Simulation sim = spinning_dimer(0.02, 0.0058);
  sim.run(1);
  REQUIRE(find_fragments(sim).fragments.size() == 1);
  CHECK(judge_fates(sim, {}, sim.time()).reason.empty());
  CHECK(fragments_after(sim, 2000.0) == 1);
}
