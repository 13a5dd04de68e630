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

// One finished case of a group: the search axis's value and the outcome class.
struct SearchObservation {
  double value = 0.0;
  std::string outcome;  // stick | bounce | break-up | undetermined (the last carries no outcome)
};

enum class GroupState { searching, converged, budget_spent, out_of_range, error };
std::string_view to_string(GroupState state);
std::optional<GroupState> parse_group_state(std::string_view text);

// A crossing P(response) = level, in axis units, with its 95 % profile-likelihood interval.
struct CrossingEstimate {
  std::string response;
  double level = 0.5;
  std::optional<double> estimate, lower, upper;
  std::string fit;     // "maximum likelihood", "firth" (penalised, under separation) or "none"
  std::string status;  // overlapping | separated | one outcome | no data
  bool narrow_enough = false;
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

// Decides the next round of a group that has placed `cases_placed` cases (all finished: done or
// failed) with these results. Phase I, per response whose outcomes do not overlap yet: values
// evenly inside the gap between the two outcomes (Neyer 1994; Wu & Tian 2014, phase I). Phase II:
// values chosen one at a time from the candidates to minimise the posterior expected variance of
// the unfinished crossings, each weighted by its wanted half-width^-2 (a Bayesian c-/L-optimal
// design for the logistic model: Chaloner & Larntz 1989), averaged over draws of the parameters
// from the fit's normal approximation, seeded by `seed`.
RoundPlan plan_round(const BoundarySearchSpec& spec, std::vector<SearchObservation> observations, int cases_placed,
                     std::uint64_t seed);

// The crossings of every target from these results (the estimates of plan_round).
std::vector<CrossingEstimate> estimate_crossings(const BoundarySearchSpec& spec,
                                                 const std::vector<SearchObservation>& observations);

// A seed for round `round` of group `group` of a study seeded `study_seed` (splitmix64 steps).
std::uint64_t round_seed(std::uint64_t study_seed, std::int64_t group, int round);

}  // namespace aerobreak
