// The time step chosen again during a run from the speeds of the moment (StepChooser,
// docs/MODEL.md 9.2): what one choice sees and takes, that the step never exceeds the contact
// period's bound and resolves every contact that forms or lets go, and that the runs stay
// reproducible to the last bit however they are cut into stretches or wavefronts.
#include <catch2/catch.hpp>

#include <limits>

#include "engine/dem/simulation.hpp"
#include "engine/dem/step_chooser.hpp"
#include "same_state.hpp"
#include "support.hpp"

using namespace aerobreak;
using Catch::Matchers::WithinRel;

namespace {

// Two particles listed as a pair, approaching each other at 0.2, one of them 0.1 above an
// adhesive floor and falling at 0.1; a third far above the floor, falling fast.
Particles three_particles() {
  Particles p;
  p.add({0.0, 0.0, 0.6}, 0.5, testing::unit_density());
  p.add({1.2, 0.0, 0.6}, 0.5, testing::unit_density());
  p.add({0.0, 0.0, 50.0}, 0.5, testing::unit_density());
  p.velocity = {{0.1, 0.0, -0.1}, {-0.1, 0.0, -0.1}, {0.0, 0.0, -5.0}};
  return p;
}

PairList first_two_listed() {
  PairList pairs;
  pairs.row_start = {0, 1, 1, 1};
  pairs.neighbor = {1};
  pairs.contact = {-1};
  return pairs;
}

// The same state to the last bit, and the same steps chosen on the way.
void require_same_state(const Simulation& a, const Simulation& b) {
  testing::require_same_state(a, b);
  CHECK(a.step_history().choices == b.step_history().choices);
  CHECK(a.step_history().shortest == b.step_history().shortest);
}

}  // namespace

TEST_CASE("a choice takes the fastest listed pair and the fastest particle within reach of an adhesive wall") {
  const BreakOverlaps overlaps{0.01, 0.02, 0.05, 0.05};
  StepChooser chooser(1.0, overlaps, 10.0, 0.25);
  Wall floor;
  Wall side{{-100.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 0, false};  // no adhesion: its contacts have no tensile range
  const Particles p = three_particles();
  const StepChooser::Choice c = chooser.choose(p, first_two_listed(), {floor, side}, p.position, 0.4);
  CHECK_THAT(c.pair_speed, WithinRel(0.2, 1e-9));   // head-on: all of it along the line of centres
  CHECK_THAT(c.wall_speed, WithinRel(0.1, 1e-12));  // not the particle 49.5 d above the floor
  // Headroom h = 0.25 x 0.2: the pair may approach at 0.2 + 2h = 0.3, the particle the floor at 0.15.
  CHECK_THAT(c.time_step, WithinRel(0.01 / (10.0 * 0.3), 1e-9));
  CHECK(c.limit == TimeStepLimit::break_overlap);
  // Budget: the step resolves a pair at 0.3, so each velocity may depart by (0.3 - 0.2) / 2.
  CHECK_THAT(std::sqrt(chooser.budget2()), WithinRel(0.05, 1e-9));
  // The line of centres (1.2 d) turns by at most 0.1 rad while the relative velocity, 0.2 + 2 x 0.05,
  // moves the pair by 0.1 x 0.9 x 1.2 d.
  CHECK_THAT(c.hold, WithinRel(0.1 * 0.9 * 1.2 / 0.3, 1e-9));
  CHECK(chooser.reference() == p.velocity);
}

TEST_CASE("a pair moving across its line of centres counts a tenth of that motion") {
  Particles p = three_particles();
  p.velocity = {{0.0, 0.1, 0.0}, {0.0, -0.1, 0.0}, {0.0, 0.0, 0.0}};  // passing each other sideways
  StepChooser chooser(1.0, {0.01, 0.0, 0.001, 0.0}, 10.0, 0.25);
  const StepChooser::Choice c = chooser.choose(p, first_two_listed(), {}, p.position, 0.4);
  CHECK_THAT(c.pair_speed, WithinRel(0.1 * 0.2, 1e-9));
  CHECK(c.wall_speed == 0.0);
  CHECK_THAT(c.time_step, WithinRel(0.01 / (10.0 * 0.02 * (1.0 + 0.25 * 2.0)), 1e-9));
  CHECK_THAT(c.hold, WithinRel(0.1 * 0.9 * 1.2 / (0.2 + 2.0 * 0.25 * 0.02), 1e-9));
}

TEST_CASE("a pair moving apart counts its motion along the line of centres only while in contact") {
  Particles p = three_particles();
  p.velocity = {{-0.1, 0.0, 0.0}, {0.1, 0.0, 0.0}, {0.0, 0.0, 0.0}};  // head-on apart
  PairList pairs = first_two_listed();
  StepChooser chooser(1.0, {0.01, 0.0, 0.001, 0.0}, 10.0, 0.25);
  CHECK(chooser.choose(p, pairs, {}, p.position, 0.4).pair_speed == 0.0);  // it cannot touch without turning back
  pairs.contact[0] = 0;                                                    // in contact: it may let go
  CHECK_THAT(chooser.choose(p, pairs, {}, p.position, 0.4).pair_speed, WithinRel(0.2, 1e-9));
}

TEST_CASE("the step is kept while the speeds allow less than twice it, and shortened at once when they allow less") {
  Particles p = three_particles();
  StepChooser chooser(1.0, {0.01, 0.0, 0.001, 0.0}, 10.0, 0.25);
  const double allowed = chooser.choose(p, first_two_listed(), {}, p.position, 0.4).time_step;  // 0.01 / 3
  CHECK(chooser.choose(p, first_two_listed(), {}, p.position, 0.4, 0.6 * allowed).time_step == 0.6 * allowed);
  CHECK(chooser.choose(p, first_two_listed(), {}, p.position, 0.4, 0.4 * allowed).time_step == allowed);
  CHECK(chooser.choose(p, first_two_listed(), {}, p.position, 0.4, 1.5 * allowed).time_step == allowed);
}

TEST_CASE("at rest or below the adhesion speed a choice takes the contact period's bound or the adhesion speed's") {
  Particles p = three_particles();
  p.velocity.assign(3, Vec3{});
  StepChooser slow(1.0, {0.01, 0.02, 0.05, 0.05}, 10.0);
  const StepChooser::Choice at_rest = slow.choose(p, first_two_listed(), {Wall{}}, p.position, 0.4);
  CHECK_THAT(at_rest.time_step, WithinRel(0.01 / (10.0 * 0.05), 1e-12));  // as if approaching at 0.05
  CHECK_THAT(std::sqrt(slow.budget2()), WithinRel(0.05 / 2.0, 1e-9));
  StepChooser capped(0.001, {0.01, 0.02, 0.05, 0.05}, 10.0);
  const StepChooser::Choice c = capped.choose(p, first_two_listed(), {Wall{}}, p.position, 0.4);
  CHECK(c.time_step == 0.001);
  CHECK(c.limit == TimeStepLimit::contact_period);
  CHECK_THAT(std::sqrt(capped.budget2()), WithinRel(0.01 / (10.0 * 0.001) / 2.0, 1e-9));  // (1 - 0) / 2
}

TEST_CASE("the adaptive step stays within the contact period's bound and resolves every contact event of an impact") {
  // A relaxed cluster of 150 primaries at gamma/k_n = 0.001 hitting an adhesive floor at 0.2 d/tau:
  // the fixed automatic step resolves the adhesion loop at twice the impact speed throughout; the
  // adaptive one at the speeds each moment has (finer than the fixed one while pairs part at more
  // than twice the impact speed, coarser after). Measured on this build over 150 tau: 19,100
  // steps of 0.0026-0.026 tau against 48,871 of 0.0031 tau; fewest steps per break overlap 14.2
  // (pairs) and 12.5 (wall) against 15.4 and 24.3.
  Particles p = testing::relaxed_cluster(150, 3, 0.001);
  testing::launch_above_floor(p, 0.51, {0.0, 0.0, -0.2});
  SimulationSettings fixed = testing::bonded();
  fixed.adaptive_time_step = false;
  fixed.speed_scale = 0.2;
  SimulationSettings adaptive = fixed;
  adaptive.adaptive_time_step = true;
  Simulation a(p, {testing::unit_material(0.001)}, {Wall{}}, testing::full_model(), adaptive);
  Simulation f(p, {testing::unit_material(0.001)}, {Wall{}}, testing::full_model(), fixed);
  REQUIRE(a.adaptive_time_step());
  REQUIRE_FALSE(f.adaptive_time_step());
  a.run(std::numeric_limits<std::int64_t>::max(), 150.0);
  f.run(std::numeric_limits<std::int64_t>::max(), 150.0);
  const StepHistory& h = a.step_history();
  const double cap = a.time_step_estimate().period / a.time_step_estimate().steps_per_period;
  INFO("adaptive: steps " << h.steps << ", dt " << h.shortest << " - " << h.longest << ", choices " << h.choices
                          << ", fewest steps per break overlap: pairs "
                          << a.pair_events().fewest_steps_per_break_overlap << ", wall "
                          << a.wall_events().fewest_steps_per_break_overlap << "; fixed: steps " << f.step_count()
                          << ", dt " << f.time_step() << ", pairs " << f.pair_events().fewest_steps_per_break_overlap
                          << ", wall " << f.wall_events().fewest_steps_per_break_overlap);
  REQUIRE(a.pair_events().broken > 10);
  REQUIRE(a.wall_events().made > 10);
  CHECK(h.longest <= cap);
  CHECK(h.longest > 2.0 * h.shortest);
  CHECK(h.steps < f.step_count());
  CHECK(h.contact_period_steps + h.break_overlap_steps == h.steps);
  CHECK(f.step_history().choices == 1);
  // Every contact that formed or let go crossed its break overlap in at least (about) the 10 steps
  // asked for: a velocity may exceed its budget for one step's kick before the next choice.
  CHECK(a.pair_events().fewest_steps_per_break_overlap >= 9.0);
  CHECK(a.wall_events().fewest_steps_per_break_overlap >= 9.0);
}

TEST_CASE("with the adaptive step one run, stretches stopped by time, single steps and wavefronts agree to the bit") {
  Particles p = testing::relaxed_cluster(600, 5);
  testing::launch_above_floor(p, 0.52, {0.01, 0.0, -0.2});
  const std::vector<Wall> walls = testing::floor_and_side_walls();
  SimulationSettings settings = testing::bonded();
  settings.body.gravity = {0.0, 0.0, -1e-4};
  settings.wavefront_depth = 1;
  SimulationSettings deep = settings;
  deep.wavefront_depth = GENERATE(5, 16);
  deep.wavefront_min_particles = 0;
  const auto make = [&](const SimulationSettings& s) {
    return Simulation(p, {testing::unit_material(0.01)}, walls, testing::full_model(), s);
  };
  Simulation whole = make(settings), stepped = make(settings), stretches = make(settings), wave = make(deep);
  const std::int64_t steps = 1500;
  whole.run(steps);
  for (std::int64_t s = 0; s < steps; ++s) stepped.step();
  for (double until = 0.7; stretches.step_count() < steps; until += 0.7)
    stretches.run(steps - stretches.step_count(), until);
  for (int call = 0; call < 3; ++call) wave.run(steps / 3);
  REQUIRE(whole.adaptive_time_step());
  REQUIRE(whole.step_history().choices > 10);
  REQUIRE(whole.step_history().shortest < whole.step_history().longest);
  REQUIRE(whole.wall_events().made > 0);
  REQUIRE(wave.wavefront_steps() > 100);
  require_same_state(whole, stepped);
  require_same_state(whole, stretches);
  require_same_state(whole, wave);
}
