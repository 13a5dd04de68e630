// A benchmark program, not a test: does an early verdict give the outcome that running on to the
// quiet rule gives? For each seed it runs one impact and watches it with two settle monitors, one
// with every rule (the default: quiet, outcome-fixed and fates-fixed, docs/IMPACT.md section 4) and
// one with the quiet rule alone; it notes the first verdict, runs on until the quiet rule settles
// (or the time limit comes), and prints both: class, retained mass fraction, fragments, largest
// fragment, normal restitution, the time of the verdict and the CPU seconds of the run up to it.
// A run that the quiet rule does not settle before the time limit is compared with its state at the
// limit instead (rule "limit": the fragments then, classed by their instantaneous velocities).
//
// usage: verdict_bench CASE.json PATCH SEEDS
//   PATCH: a JSON merge patch applied to the case first ('{}' for none), e.g. the regime's speed
//   SEEDS: a count S (seeds 1 .. S) or a range A-B (seeds A .. B); seed s adds s to the generator's seed
//   and is the orientation seed
// Prints one line per seed and a summary: seeds whose class, retained fraction, fragment count or
// largest fragment differ, the largest restitution difference, and the CPU seconds to either verdict.
// Each seed's lines are flushed as it ends, so that a run cut short keeps the seeds it finished.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/core/run_clock.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/impact_case.hpp"
#include "engine/impact/fragments.hpp"
#include "engine/impact/impact_run.hpp"
#include "engine/impact/settle.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;

namespace {

struct Verdict {
  bool settled = false;
  std::string outcome = "undetermined";
  std::string rule = "-";
  double retained = NAN;
  std::size_t fragments = 0;
  std::size_t largest = 0;
  double restitution = NAN;
  double time = NAN;
  double cpu_seconds = NAN;
};

Verdict verdict_of(const std::vector<Fragment>& fragments, const std::vector<Vec3>& velocity, const ImpactCase& c,
                   const Vec3& impact_velocity) {
  Verdict v;
  const Vec3 normal{0.0, 0.0, 1.0};
  const Classification k = classify(fates_of(fragments, velocity, normal), true, c.thresholds);
  v.outcome = to_string(k.outcome);
  v.retained = k.retained_mass_fraction;
  v.fragments = fragments.size();
  v.largest = fragments.front().size;
  v.restitution = -dot(velocity.front(), normal) / dot(impact_velocity, normal);
  return v;
}

Verdict verdict_of(const SettleMonitor& monitor, const ImpactCase& c, const Vec3& impact_velocity, double cpu) {
  Verdict v = verdict_of(monitor.judged_fragments().fragments, monitor.judged_mean_velocities(), c, impact_velocity);
  v.settled = true;
  v.rule = to_string(monitor.rule());
  v.time = monitor.settled_at();
  v.cpu_seconds = cpu;
  return v;
}

// The state at the time limit of a run that the quiet rule did not settle.
Verdict state_at_limit(const Simulation& sim, const ImpactCase& c, const Vec3& impact_velocity, double cpu) {
  const std::vector<Fragment> fragments = find_fragments(sim).fragments;
  std::vector<Vec3> velocity;
  for (const Fragment& f : fragments) velocity.push_back(f.velocity);
  Verdict v = verdict_of(fragments, velocity, c, impact_velocity);
  v.rule = "limit";
  v.time = sim.time();
  v.cpu_seconds = cpu;
  return v;
}

// Runs seed `seed` of the case, both monitors looking every window/20 of simulated time.
std::pair<Verdict, Verdict> run_seed(Json document, int seed) {
  document["cluster"]["generator"]["seed"] = document["cluster"]["generator"].value("seed", 0) + seed;
  document["impact"]["orientation_seed"] = seed;
  const ImpactCase c = parse_impact_case(document);
  PreparedImpact prepared = prepare_impact(c);
  Simulation& sim = *prepared.simulation;
  const ImpactResult& r = prepared.result;
  SettleMonitor early(r.quiet_window, r.rest_speed, c.thresholds, true, c.settle.follow_rigid_turn);
  SettleMonitor quiet(r.quiet_window, r.rest_speed, c.thresholds, false);
  early.update(sim);
  quiet.update(sim);
  const RunClock clock;
  const double check = r.quiet_window / 20.0;
  Verdict first, last;
  for (double next = check; sim.time() < c.time_limit && !quiet.settled(); next += check) {
    sim.run(std::numeric_limits<std::int64_t>::max(), std::min(next, c.time_limit));
    if (!first.settled && early.update(sim))
      first = verdict_of(early, c, r.impact_velocity, clock.elapsed().cpu_seconds);
    if (quiet.update(sim)) last = verdict_of(quiet, c, r.impact_velocity, clock.elapsed().cpu_seconds);
  }
  if (!quiet.settled()) last = state_at_limit(sim, c, r.impact_velocity, clock.elapsed().cpu_seconds);
  return {first, last};
}

void print(int seed, const char* which, const Verdict& v) {
  std::printf("%4d %-6s %-12s %-13s %8.4f %5zu %7zu %8.4f %10.1f %8.2f\n", seed, which, v.outcome.c_str(),
              v.rule.c_str(), v.retained, v.fragments, v.largest, v.restitution, v.time, v.cpu_seconds);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: verdict_bench CASE.json PATCH SEEDS\n");
    return 2;
  }
  Json document = Json::parse(std::ifstream(argv[1]));
  document.merge_patch(Json::parse(argv[2]));
  const std::string range = argv[3];
  const std::size_t dash = range.find('-');
  const int first_seed = dash == std::string::npos ? 1 : std::stoi(range.substr(0, dash));
  const int last_seed = std::stoi(dash == std::string::npos ? range : range.substr(dash + 1));
  std::printf("%4s %-6s %-12s %-13s %8s %5s %7s %8s %10s %8s\n", "seed", "rule", "class", "settled by", "retained",
              "frags", "largest", "e_n", "time", "CPU s");
  int differ = 0, early_seeds = 0, no_verdict = 0, against_limit = 0;
  double worst_restitution = 0.0, cpu_early = 0.0, cpu_quiet = 0.0;
  for (int s = first_seed; s <= last_seed; ++s) {
    const auto [first, last] = run_seed(document, s);
    print(s, "first", first);
    print(s, "quiet", last);
    if (!first.settled) {
      ++no_verdict;
      continue;
    }
    if (!last.settled) ++against_limit;
    if (first.rule != "quiet") ++early_seeds;
    if (first.outcome != last.outcome || std::abs(first.retained - last.retained) > 1e-12 ||
        first.fragments != last.fragments || first.largest != last.largest)
      ++differ;
    worst_restitution = std::max(worst_restitution, std::abs(first.restitution - last.restitution));
    cpu_early += first.cpu_seconds;
    cpu_quiet += last.cpu_seconds;
  }
  std::printf(
      "summary: %d seeds, %d without a verdict by the time limit, %d settled first by another rule than "
      "quiet, %d compared with the state at the time limit (the quiet rule never settled); %d "
      "differ from the quiet rule's outcome (class, retained, fragments, largest); largest restitution "
      "difference %.3g; CPU s to the first verdict %.2f, to the quiet rule's (or the limit) %.2f\n",
      last_seed - first_seed + 1, no_verdict, early_seeds, against_limit, differ, worst_restitution, cpu_early,
      cpu_quiet);
  return 0;
}
