#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orchestrator/study/study_search.hpp"

// The decisions of an adaptive boundary search (docs/ADAPTIVE.md), as pure functions of a group's
// results: no store, no clock. The same results, in any order, give the same plan.
namespace aerobreak {

// One finished case of a group: the search axis's value, the outcome class and the round that
// placed it.
struct SearchObservation {
  double value = 0.0;
  std::string outcome;  // stick | bounce | break-up | undetermined (the last carries no outcome)
  int round = 0;
};

// A search stops no earlier than this many determined results in a group (docs/ADAPTIVE.md,
// "Stopping"): the pilot size of a fixed-width sequential interval (Chow & Robbins, Ann. Math.
// Statist. 36 (1965) 457), below which a narrow interval is too often narrow by chance.
inline constexpr std::size_t kMinimumSearchResults = 80;

enum class GroupState { searching, converged, budget_spent, out_of_range, error };
std::string_view to_string(GroupState state);

// A crossing P(response) = level, in axis units, with its 95 % profile-likelihood interval.
struct CrossingEstimate {
  std::string response;
  double level = 0.5;
  std::optional<double> estimate, lower, upper;
  std::string fit;             // "firth" (Firth's penalised likelihood, response_fit.hpp) or "none"
  std::string status;          // overlapping | separated | one outcome | no data
  bool narrow_enough = false;  // the interval, and the one expected from the draws, as narrow as asked
  bool found = false;          // the stopping rule holds: narrow now and at the decision before, enough results
};

// Which round is decided, after how many cases, and the seeds of its draws and of the previous
// decision's (whose narrowness the stopping rule checks again).
struct RoundContext {
  int round = 1;  // round 0 is placed with the study
  int cases_placed = 0;
  std::uint64_t seed = 0;
  std::uint64_t previous_seed = 0;
};

// What one round does: the group's state, the estimates the decision rests on, and the values of
// the new cases (empty unless still searching), with why each was placed.
struct RoundPlan {
  GroupState state = GroupState::searching;
  std::vector<CrossingEstimate> estimates;
  std::vector<double> values;
  std::vector<std::string> reasons;  // per value: "bracket break-up" (phase I) or "optimal" (phase II)
  std::size_t results = 0;           // determined results the fits used
};

// Whether the design weighs each candidate by the chance that a case there ends determined
// (determined_chance.hpp; docs/ADAPTIVE.md, "Undetermined outcomes"), or ignores undetermined
// outcomes (the design before: the benchmark's reference).
enum class UndeterminedWeighting { by_chance, none };

// Decides round `context.round` of a group that has placed `context.cases_placed` cases (all
// finished: done or failed) with these results (those of the rounds before it). Phase I, per
// response whose outcomes do not overlap yet: values evenly inside the gap between the two
// outcomes (Neyer 1994; Wu & Tian 2014, phase I). Phase II:
// values chosen one at a time from the candidates to minimise the posterior expected variance of
// the unfinished crossings, each weighted by its wanted half-width^-2 (a Bayesian c-/L-optimal
// design for the logistic model: Chaloner & Larntz 1989), averaged over draws of the parameters
// from the fit's normal approximation, seeded by `context.seed`. A crossing is found when it is
// narrow enough on these results and was on those of the rounds before the last (with the
// previous seed), and the group has kMinimumSearchResults results (docs/ADAPTIVE.md, "Stopping").
// Both phases weigh each candidate by the chance that a case there ends determined (`weighting`).
RoundPlan plan_round(const BoundarySearchSpec& spec, std::vector<SearchObservation> observations,
                     const RoundContext& context, UndeterminedWeighting weighting = UndeterminedWeighting::by_chance);

// The crossings of every target from these results, with the stopping rule's verdict (the
// estimates of plan_round).
std::vector<CrossingEstimate> estimate_crossings(const BoundarySearchSpec& spec,
                                                 std::vector<SearchObservation> observations,
                                                 const RoundContext& context);

// A seed for round `round` of group `group` of a study seeded `study_seed` (splitmix64 steps).
std::uint64_t round_seed(std::uint64_t study_seed, std::int64_t group, int round);

// The context of round `round` of a group: its seed and the previous round's.
RoundContext round_context(std::uint64_t study_seed, std::int64_t group, int round, int cases_placed);

}  // namespace aerobreak
