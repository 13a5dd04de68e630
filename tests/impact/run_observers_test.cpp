// The impact run loop: observers see the simulation at the first step at or past each moment of
// simulated time they ask for (or at their step counts), in their order, one can stop the run, the
// stepping in stretches gives the trajectory of one uninterrupted run to the last bit, snapshots
// are never taken twice at a step, progress reports follow their wall-clock interval and come at
// every stop, the schedule follows the case in simulated time, and a whole impact ends in the
// state of the plain Simulation run for as many steps.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "engine/dem/simulation.hpp"
#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_result.hpp"
#include "engine/impact/impact_run.hpp"
#include "engine/impact/run_observers.hpp"
#include "engine/impact/settle.hpp"
#include "impact_support.hpp"

using Json = nlohmann::ordered_json;
using namespace aerobreak;

namespace {

// A fixed step of 1/16 tau, a power of two: every multiple of it is exact, so that the steps at
// which the observers look are known. `adaptive` runs the automatic step instead.
constexpr double kStep = 0.0625;
PreparedImpact small_impact(bool adaptive = false) {
  auto document = testing::minimal_case();
  if (!adaptive) document["run"]["time_step"] = kStep;
  return prepare_impact(parse_impact_case(document));
}

// Records the steps it looks at (into a log shared with other observers) and stops at `stop_at`.
// Its interval is in steps of kStep.
class Recorder final : public IntervalObserver {
 public:
  Recorder(int id, std::int64_t interval, std::vector<std::pair<int, std::int64_t>>& log, std::int64_t stop_at = -1)
      : IntervalObserver(static_cast<double>(interval) * kStep, 0.0), id_(id), log_(log), stop_at_(stop_at) {}

 private:
  bool look(const Simulation& sim) override {
    log_.emplace_back(id_, sim.step_count());
    return sim.step_count() == stop_at_;
  }
  int id_;
  std::vector<std::pair<int, std::int64_t>>& log_;
  std::int64_t stop_at_;
};

void require_same_particles(const Simulation& a, const Simulation& b) {
  REQUIRE(a.step_count() == b.step_count());
  for (std::size_t i = 0; i < a.particles().size(); ++i) {
    CHECK(a.particles().position[i] == b.particles().position[i]);
    CHECK(a.particles().velocity[i] == b.particles().velocity[i]);
    CHECK(a.particles().angular_velocity[i] == b.particles().angular_velocity[i]);
  }
}

}  // namespace

TEST_CASE("observers see the simulation at each of their own moments, in their order, up to the limit") {
  PreparedImpact run = small_impact();
  std::vector<std::pair<int, std::int64_t>> log;
  Recorder every3(1, 3, log), every5(2, 5, log);
  CHECK_FALSE(run_observed(*run.simulation, 16 * kStep, {&every3, &every5}));
  CHECK(run.simulation->step_count() == 16);
  const std::vector<std::pair<int, std::int64_t>> expected{{1, 3},  {2, 5},  {1, 6},  {1, 9},
                                                           {2, 10}, {1, 12}, {1, 15}, {2, 15}};
  CHECK(log == expected);
}

TEST_CASE("an observer stops the run at its step, and those after it in the list do not look then") {
  PreparedImpact run = small_impact();
  std::vector<std::pair<int, std::int64_t>> log;
  Recorder stopper(1, 5, log, 10), other(2, 5, log);
  CHECK(run_observed(*run.simulation, 100 * kStep, {&stopper, &other}));
  CHECK(run.simulation->step_count() == 10);
  const std::vector<std::pair<int, std::int64_t>> expected{{1, 5}, {2, 5}, {1, 10}};
  CHECK(log == expected);
}

TEST_CASE("stepping in stretches between observers gives the uninterrupted run to the last bit") {
  // At the automatic step, chosen again from the speeds of the moment: the observers' moments
  // fall anywhere within steps of changing length.
  PreparedImpact observed = small_impact(true), plain = small_impact(true);
  std::vector<std::pair<int, std::int64_t>> log;
  Recorder a(1, 7, log), b(2, 11, log), c(3, 1, log);
  run_observed(*observed.simulation, 500 * kStep, {&a, &b, &c});
  REQUIRE(observed.simulation->step_history().choices > 1);
  plain.simulation->run(observed.simulation->step_count());
  require_same_particles(*observed.simulation, *plain.simulation);
  CHECK(observed.simulation->energy().mechanical() == plain.simulation->energy().mechanical());
}

TEST_CASE("snapshots come at their interval and never twice at one step, an interval of 0 means none") {
  PreparedImpact run = small_impact();
  std::vector<std::int64_t> steps;
  SnapshotObserver snapshots([&](const Simulation& s) { steps.push_back(s.step_count()); }, 4 * kStep);
  snapshots.take(*run.simulation);
  run_observed(*run.simulation, 12 * kStep, {&snapshots});
  snapshots.take(*run.simulation);  // the end falls on a snapshot step: not taken again
  CHECK(steps == std::vector<std::int64_t>{0, 4, 8, 12});
  CHECK(snapshots.taken() == 4);
  SnapshotObserver never([&](const Simulation&) { FAIL("no snapshot expected"); }, 0);
  CHECK(never.next_step() == std::numeric_limits<std::int64_t>::max());
  CHECK(never.next_time() == std::numeric_limits<double>::infinity());
}

TEST_CASE("progress is reported at its step interval once its wall-clock interval has passed") {
  PreparedImpact run = small_impact();
  std::vector<ImpactProgress> reports;
  ProgressObserver always([&](const ImpactProgress& p) { reports.push_back(p); }, 0.0, 100.0, 10);
  ProgressObserver rarely([&](const ImpactProgress&) { FAIL("no report expected within an hour"); }, 3600.0, 100.0, 10);
  run_observed(*run.simulation, 30 * kStep, {&always, &rarely});
  REQUIRE(reports.size() == 3);
  CHECK(reports.back().steps == 30);
  CHECK(reports.back().time == run.simulation->time());
  CHECK(reports.back().time_limit == 100.0);
  CHECK(reports.back().fragments >= 1);
  CHECK(always.reports() == 3);
  CHECK(rarely.reports() == 0);
}

TEST_CASE("progress also looks whenever the run stops for another observer") {
  PreparedImpact run = small_impact();
  std::vector<std::pair<int, std::int64_t>> log;
  Recorder every4(1, 4, log);
  std::vector<std::int64_t> reported;
  ProgressObserver progress([&](const ImpactProgress& p) { reported.push_back(p.steps); }, 0.0, 100.0, 100);
  run_observed(*run.simulation, 12 * kStep, {&every4, &progress});
  CHECK(reported == std::vector<std::int64_t>{4, 8, 12});
}

TEST_CASE("the settle check stops the run when the monitor finds the outcome settled") {
  PreparedImpact run = small_impact();
  const ImpactResult& r = run.result;
  SettleMonitor monitor(r.quiet_window, r.rest_speed, r.impact_case.thresholds);
  const ImpactSchedule schedule = impact_schedule(r, run.simulation->particles().size());
  SettleObserver settle(monitor, schedule.check_interval);
  monitor.update(*run.simulation);
  CHECK(run_observed(*run.simulation, r.impact_case.time_limit, {&settle}));
  CHECK(monitor.settled());
  // At the first step at or past a multiple of the check interval.
  const double checks = std::floor(run.simulation->time() / schedule.check_interval);
  CHECK(run.simulation->time() - kStep < checks * schedule.check_interval);
  CHECK(run.simulation->time() == monitor.settled_at());
}

TEST_CASE("the schedule follows the case in simulated time: 20 checks per quiet window, snapshot interval") {
  auto document = testing::minimal_case();
  document["run"]["snapshot_interval"] = 10.0;
  document["run"]["time_step"] = 0.05;
  PreparedImpact fixed = prepare_impact(parse_impact_case(document));
  const ImpactSchedule s = impact_schedule(fixed.result, 8);
  CHECK(s.check_interval == fixed.result.quiet_window / 20.0);
  CHECK(s.snapshot_interval == 10.0);
  CHECK(s.progress_steps == 125000);  // 10^6 particle-steps of 8 primaries
  // The same window and checks whatever the step: the window comes from the contact period of
  // the automatic estimate, which a fixed step computes too.
  document["run"].erase("time_step");
  PreparedImpact automatic = prepare_impact(parse_impact_case(document));
  CHECK(automatic.result.time_step != fixed.result.time_step);
  CHECK(automatic.result.quiet_window == fixed.result.quiet_window);
  CHECK(impact_schedule(automatic.result, 8).check_interval == s.check_interval);
}

TEST_CASE("the automatic quiet window is the case's share of the time to cross the cluster's extent") {
  auto document = testing::minimal_case();
  document["impact"]["speed"] = 0.0005;  // slow: the crossing time, not 50 contact periods, sets the window
  const PreparedImpact tenth = prepare_impact(parse_impact_case(document));
  document["run"]["settle"]["extent_crossing_fraction"] = 0.5;
  const PreparedImpact half = prepare_impact(parse_impact_case(document));
  REQUIRE(tenth.result.quiet_window > 50.0 * tenth.result.time_step_estimate.period);
  CHECK_THAT(half.result.quiet_window, Catch::Matchers::WithinRel(5.0 * tenth.result.quiet_window, 1e-12));
  CHECK(half.result.time_step == tenth.result.time_step);
}

TEST_CASE("a whole impact ends in the state of the plain simulation run for as many steps") {
  auto document = testing::minimal_case();
  document["run"]["snapshot_interval"] = 50.0;
  const ImpactCase impact_case = parse_impact_case(document);
  ImpactRunOptions options;
  Particles last;
  std::size_t frames = 0;
  options.snapshot = [&](const Simulation& s) {
    last = s.particles();
    ++frames;
  };
  options.progress = [](const ImpactProgress&) {};
  options.progress_seconds = 0.0;
  const ImpactResult result = run_impact(impact_case, options);
  REQUIRE(result.settled);
  CHECK(result.snapshots == frames);
  PreparedImpact plain = prepare_impact(impact_case);
  plain.simulation->run(result.steps);
  const Particles& p = plain.simulation->particles();
  REQUIRE(last.size() == p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    CHECK(last.position[i] == p.position[i]);
    CHECK(last.velocity[i] == p.velocity[i]);
    CHECK(last.angular_velocity[i] == p.angular_velocity[i]);
  }
  CHECK(result.final_energy.mechanical() == plain.simulation->energy().mechanical());
}

TEST_CASE("the result records the step history: the adaptive step's range and limits, a fixed step's one value") {
  // A fast impact of a weakly adhesive cluster: the break overlaps set the step, shorter while the
  // approaches are fast (docs/MODEL.md 9.2).
  auto document = testing::minimal_case();
  document["material"]["gamma_over_kn"] = 0.001;
  document["impact"]["speed"] = 0.1;
  const ImpactResult adaptive = run_impact(parse_impact_case(document));
  const StepHistory& h = adaptive.step_history;
  const double cap = adaptive.time_step_estimate.period / adaptive.time_step_estimate.steps_per_period;
  REQUIRE(adaptive.settled);
  CHECK(h.steps == adaptive.steps);
  CHECK(h.contact_period_steps + h.break_overlap_steps == h.steps);
  CHECK(h.break_overlap_steps > 0);
  CHECK(h.choices > 1);
  CHECK(h.shortest < h.mean());
  CHECK(h.mean() < h.longest);
  CHECK(h.longest <= cap);
  CHECK_THAT(h.time, Catch::Matchers::WithinRel(adaptive.simulated_time, 1e-9));
  const Json recorded = to_json(adaptive)["run"];
  CHECK(recorded["time_step_source"] == "adaptive");
  CHECK(recorded["time_step_history"]["shortest"] == h.shortest);
  CHECK(recorded["time_step_history"]["mean"] == h.mean());
  CHECK(recorded["time_step_history"]["steps_at_break_overlap"] == h.break_overlap_steps);
  CHECK(recorded["time_step_history"]["choices"] == h.choices);
  CHECK(recorded["settled_by"] == to_string(adaptive.settled_by));
  // Run again, the run is the same to the last bit: the steps chosen depend on the state alone.
  const ImpactResult again = run_impact(parse_impact_case(document));
  CHECK(again.steps == adaptive.steps);
  CHECK(again.simulated_time == adaptive.simulated_time);
  CHECK(again.step_history.shortest == h.shortest);
  CHECK(again.step_history.choices == h.choices);
  CHECK(to_json(again)["fragments"] == to_json(adaptive)["fragments"]);

  document["run"]["time_step"] = kStep;
  const ImpactResult fixed = run_impact(parse_impact_case(document));
  CHECK(fixed.step_history.shortest == kStep);
  CHECK(fixed.step_history.longest == kStep);
  CHECK(fixed.step_history.choices == 0);
  CHECK(fixed.step_history.contact_period_steps == fixed.steps);
  CHECK(to_json(fixed)["run"]["time_step_source"] == "fixed");
}
