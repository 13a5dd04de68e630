#pragma once
// Adaptive searches and uniform grids run on the synthetic law directly (no store, no processes):
// the many repetitions of the coverage test and of the benchmark (docs/ADAPTIVE.md, "Validation").
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "orchestrator/search/boundary_search.hpp"
#include "orchestrator/search/optimal_design.hpp"
#include "tests/support/synthetic_law.hpp"

namespace aerobreak::testing {

// A search for v50 of the impact speed over 0.005-0.3 d/tau, in rounds of 10 after 10 initial
// cases: the setting of the coverage test and the benchmark.
inline BoundarySearchSpec speed_search(double relative_width, int budget) {
  BoundarySearchSpec spec;
  spec.axis = "impact_speed";
  spec.pointer = "/impact/speed";
  spec.from = 0.005;
  spec.to = 0.3;
  spec.targets = {{"break-up", {0.5}}};
  spec.relative_width = relative_width;
  spec.budget = budget;
  spec.batch = 10;
  spec.initial = 10;
  return spec;
}

struct SimulatedSearch {
  RoundPlan final;  // the last decision: state and estimates
  int cases = 0;
  int rounds = 0;
  int undetermined = 0;                     // cases that ended undetermined
  std::vector<std::vector<double>> placed;  // the values of each round after round 0
};

// Where cases end undetermined (the impact hits its time limit), as the engine's do at the
// slowest and fastest impacts: below `below` or above `above` (axis values), each with `chance`.
struct UndeterminedBand {
  double below = 0.0;
  double above = INFINITY;
  double chance = 0.0;
  bool contains(double value) const { return value < below || value > above; }
};

// Outcomes of one simulated experiment: independent draws from the law, in order; a case in the
// band draws once more, whether it ends undetermined.
class SimulatedOutcomes {
 public:
  SimulatedOutcomes(SyntheticLaw law, double gamma_over_kn, std::uint64_t seed, UndeterminedBand band = {})
      : law_(law), gamma_(gamma_over_kn), state_(seed), band_(band) {}
  SearchObservation at(double value, int round) {
    const double u = uniform();
    if (band_.contains(value) && uniform() < band_.chance) return {value, "undetermined", round};
    return {value, law_.outcome(value, gamma_, u), round};
  }

 private:
  double uniform() { return static_cast<double>(splitmix64(state_) >> 11) * 0x1.0p-53; }
  SyntheticLaw law_;
  double gamma_;
  std::uint64_t state_;
  UndeterminedBand band_;
};

// A whole search of one group: round 0, then plan_round until the group ends.
inline SimulatedSearch simulate_search(const BoundarySearchSpec& spec, const SyntheticLaw& law, double gamma_over_kn,
                                       std::uint64_t seed, UndeterminedBand band = {},
                                       UndeterminedWeighting weighting = UndeterminedWeighting::by_chance) {
  SimulatedOutcomes outcomes(law, gamma_over_kn, seed, band);
  std::vector<SearchObservation> observations;
  const auto candidates = search_candidates(spec);
  for (const auto index : initial_search_indices(spec)) observations.push_back(outcomes.at(candidates[index], 0));
  SimulatedSearch out;
  out.rounds = 1;
  for (;;) {
    out.cases = static_cast<int>(observations.size());
    out.undetermined = static_cast<int>(std::count_if(observations.begin(), observations.end(),
                                                      [](const auto& o) { return o.outcome == "undetermined"; }));
    out.final = plan_round(spec, observations, round_context(seed, 0, out.rounds, out.cases), weighting);
    if (out.final.state != GroupState::searching) return out;
    out.placed.push_back(out.final.values);
    for (const double value : out.final.values) observations.push_back(outcomes.at(value, out.rounds));
    ++out.rounds;
  }
}

}  // namespace aerobreak::testing
