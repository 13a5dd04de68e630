#include "orchestrator/search/boundary_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "orchestrator/search/determined_chance.hpp"
#include "orchestrator/search/optimal_design.hpp"
#include "orchestrator/search/response_fit.hpp"

namespace aerobreak {
namespace {

constexpr double kZ95 = 1.959963984540054;  // the normal 0.975 quantile

constexpr std::array<std::pair<GroupState, std::string_view>, 5> kStates{{
    {GroupState::searching, "searching"},
    {GroupState::converged, "converged"},
    {GroupState::budget_spent, "budget_spent"},
    {GroupState::out_of_range, "out_of_range"},
    {GroupState::error, "error"},
}};

std::vector<ResponseFit> fit_targets(const BoundarySearchSpec& spec, std::vector<SearchObservation>& observations) {
  std::sort(observations.begin(), observations.end(), [](const auto& a, const auto& b) {
    return a.value != b.value ? a.value < b.value : a.outcome < b.outcome;
  });
  std::vector<ResponseFit> fits;
  for (const auto& target : spec.targets) fits.push_back(fit_response(spec, observations, target.response));
  return fits;
}

// Whether each crossing's profile interval is as narrow as asked and the expected interval over the
// parameters' uncertainty is too: a stop on the realised width alone ends some groups after a few
// cases on a lucky narrow interval, whose coverage is poor (docs/ADAPTIVE.md).
std::vector<CrossingEstimate> crossings(const BoundarySearchSpec& spec, const std::vector<ResponseFit>& fits,
                                        std::uint64_t seed) {
  std::vector<CrossingEstimate> out;
  for (std::size_t t = 0; t < spec.targets.size(); ++t)
    for (const double level : spec.targets[t].levels) {
      CrossingEstimate estimate = crossing(spec, fits[t], level);
      if (estimate.narrow_enough) {
        const double half = wanted_half_width(spec, search_dose(spec, *estimate.estimate));
        const double variance = expected_crossing_variance({&fits[t], level, half}, seed);
        estimate.narrow_enough = kZ95 * std::sqrt(variance) <= half;
      }
      out.push_back(std::move(estimate));
    }
  return out;
}

// The stopping rule (docs/ADAPTIVE.md, "Stopping"): a crossing is found when it is narrow enough
// now and was on the results of the previous decision (the rounds before the last), once the
// group has kMinimumSearchResults results. Stopping the moment an interval first looks narrow
// selects intervals narrow by chance; the confirmation and the pilot size (Chow & Robbins 1965)
// bring the coverage back to its nominal rate.
void judge(const BoundarySearchSpec& spec, const std::vector<SearchObservation>& observations,
           const RoundContext& context, std::vector<CrossingEstimate>& estimates) {
  const auto results = std::count_if(observations.begin(), observations.end(),
                                     [](const auto& o) { return o.outcome != "undetermined"; });
  const bool narrow = std::any_of(estimates.begin(), estimates.end(), [](const auto& e) { return e.narrow_enough; });
  if (!narrow || static_cast<std::size_t>(results) < kMinimumSearchResults) return;
  std::vector<SearchObservation> earlier;
  for (const auto& o : observations)
    if (o.round < context.round - 1) earlier.push_back(o);
  const auto before = crossings(spec, fit_targets(spec, earlier), context.previous_seed);
  for (std::size_t e = 0; e < estimates.size(); ++e)
    estimates[e].found = estimates[e].narrow_enough && before[e].narrow_enough;
}

// The candidates as the fits see them: doses centred on the range's middle.
std::vector<double> candidate_doses(const BoundarySearchSpec& spec, const std::vector<double>& values) {
  std::vector<double> doses;
  for (const double v : values) doses.push_back(search_dose(spec, v) - search_centre(spec));
  return doses;
}

// `count` of the candidates `inside` spread evenly in their expected determined results: each owns
// a share q of the line, the gap's ends half a share each, and pick k is the owner of the point
// (k + 1) / (count + 1) along it (with every q = 1 the even spread). Where a part of the gap times
// out, its cases go to the rest of it: the gap stays as it is while its cases end undetermined.
std::vector<std::size_t> spread_by_chance(const std::vector<std::size_t>& inside, const std::vector<double>& chances,
                                          std::size_t count) {
  double total = 0.0;
  for (const auto c : inside) total += chances[c];
  std::vector<std::size_t> picked;
  for (std::size_t k = 0; k < count; ++k) {
    const double point = (static_cast<double>(k) + 1.0) * (total + 1.0) / (static_cast<double>(count) + 1.0);
    std::size_t owner = 0;
    double next = 0.5 + chances[inside[0]];  // where the share of the candidate after the owner begins
    while (owner + 1 < inside.size() && next <= point) next += chances[inside[++owner]];
    picked.push_back(inside[owner]);
  }
  return picked;
}

// Phase I: `count` candidates spread evenly strictly inside the gap (one: its middle, a
// bisection); the candidates at its two ends in turn when none lies inside. Candidates near
// undetermined results count by their chance of a determined one (spread_by_chance). The ends
// are where determined results lie, and only cases there can end the separation when nothing
// lies between them: they are kept.
std::vector<std::size_t> gap_doses(const std::vector<double>& doses, const std::vector<double>& chances, double low,
                                   double high, std::size_t count) {
  std::vector<std::size_t> inside;
  for (std::size_t c = 0; c < doses.size(); ++c)
    if (doses[c] > low && doses[c] < high) inside.push_back(c);
  if (std::any_of(inside.begin(), inside.end(), [&](const auto c) { return chances[c] < 1.0; }))
    return spread_by_chance(inside, chances, count);
  std::vector<std::size_t> picked;
  if (inside.empty()) {
    const auto nearest = [&](double dose) {
      std::size_t best = 0;
      for (std::size_t c = 1; c < doses.size(); ++c)
        if (std::abs(doses[c] - dose) < std::abs(doses[best] - dose)) best = c;
      return best;
    };
    for (std::size_t k = 0; k < count; ++k) picked.push_back(nearest(k % 2 == 0 ? low : high));
    return picked;
  }
  const double n = static_cast<double>(inside.size());
  for (std::size_t k = 0; k < count; ++k) {
    const auto at = static_cast<std::size_t>(
                        std::lround((static_cast<double>(k) + 1.0) * (n + 1.0) / (static_cast<double>(count) + 1.0))) -
                    1;
    picked.push_back(inside[std::min(at, inside.size() - 1)]);
  }
  return picked;
}

// The round's cases shared out between the phase-I gaps of the responses that need one and the
// phase-II design of the crossings whose responses overlap, in turn, in target order.
void place(const BoundarySearchSpec& spec, const std::vector<ResponseFit>& fits,
           const std::vector<CrossingEstimate>& estimates, const std::vector<SearchObservation>& observations,
           UndeterminedWeighting weighting, std::size_t count, std::uint64_t seed, RoundPlan& plan) {
  std::vector<const ResponseFit*> gaps;
  std::vector<DesignTarget> design;
  std::size_t e = 0;
  for (std::size_t t = 0; t < spec.targets.size(); ++t) {
    bool gap_needed = false;
    for (std::size_t l = 0; l < spec.targets[t].levels.size(); ++l, ++e) {
      const auto& estimate = estimates[e];
      if (estimate.found || fits[t].overlap == Overlap::one_outcome) continue;
      if (fits[t].overlap == Overlap::separated || !estimate.estimate) {
        gap_needed = fits[t].overlap == Overlap::separated;
        continue;
      }
      const double dose = search_dose(spec, *estimate.estimate);
      design.push_back({&fits[t], estimate.level, wanted_half_width(spec, dose)});
    }
    if (gap_needed) gaps.push_back(&fits[t]);
  }
  const std::size_t sources = gaps.size() + (design.empty() ? 0 : 1);
  if (sources == 0) return;
  const auto values = search_candidates(spec);
  const auto doses = candidate_doses(spec, values);
  const auto chances = weighting == UndeterminedWeighting::by_chance ? determined_chances(spec, observations, values)
                                                                     : std::vector<double>(values.size(), 1.0);
  for (std::size_t s = 0; s < sources; ++s) {
    const std::size_t share = count / sources + (s < count % sources ? 1 : 0);
    if (share == 0) continue;
    const bool optimal = s == gaps.size();
    const auto picked = optimal ? optimal_doses(design, doses, chances, share, seed)
                                : gap_doses(doses, chances, gaps[s]->gap_low, gaps[s]->gap_high, share);
    for (const auto c : picked) {
      plan.values.push_back(values[c]);
      plan.reasons.push_back(optimal ? "optimal" : "bracket " + gaps[s]->response);
    }
  }
}

}  // namespace

std::string_view to_string(GroupState state) {
  for (const auto& [s, text] : kStates)
    if (s == state) return text;
  return "error";
}

std::vector<CrossingEstimate> estimate_crossings(const BoundarySearchSpec& spec,
                                                 std::vector<SearchObservation> observations,
                                                 const RoundContext& context) {
  auto estimates = crossings(spec, fit_targets(spec, observations), context.seed);
  judge(spec, observations, context, estimates);
  return estimates;
}

RoundPlan plan_round(const BoundarySearchSpec& spec, std::vector<SearchObservation> observations,
                     const RoundContext& context, UndeterminedWeighting weighting) {
  RoundPlan plan;
  const auto fits = fit_targets(spec, observations);
  plan.estimates = crossings(spec, fits, context.seed);
  judge(spec, observations, context, plan.estimates);
  for (const auto& o : observations) plan.results += o.outcome != "undetermined";

  bool unfinished = false, unreachable = false;
  std::size_t e = 0;
  for (std::size_t t = 0; t < spec.targets.size(); ++t)
    for (std::size_t l = 0; l < spec.targets[t].levels.size(); ++l, ++e) {
      // Round 0 spans the whole range: a response never seen, or always seen, there has its
      // crossing outside the range.
      if (fits[t].overlap == Overlap::one_outcome)
        unreachable = true;
      else if (!plan.estimates[e].found)
        unfinished = true;
    }
  if (!unfinished) {
    plan.state = unreachable ? GroupState::out_of_range : GroupState::converged;
    return plan;
  }
  if (context.cases_placed >= spec.budget) {
    plan.state = GroupState::budget_spent;
    return plan;
  }
  const auto count = static_cast<std::size_t>(std::min(spec.batch, spec.budget - context.cases_placed));
  place(spec, fits, plan.estimates, observations, weighting, count, context.seed, plan);
  if (plan.values.empty()) plan.state = unreachable ? GroupState::out_of_range : GroupState::budget_spent;
  return plan;
}

std::uint64_t round_seed(std::uint64_t study_seed, std::int64_t group, int round) {
  std::uint64_t state = study_seed ^ 0x6164617074697665ULL;  // "adaptive"
  splitmix64(state);
  state ^= static_cast<std::uint64_t>(group) * 0x9e3779b97f4a7c15ULL;
  splitmix64(state);
  state ^= static_cast<std::uint64_t>(round);
  return splitmix64(state);
}

RoundContext round_context(std::uint64_t study_seed, std::int64_t group, int round, int cases_placed) {
  return {round, cases_placed, round_seed(study_seed, group, round), round_seed(study_seed, group, round - 1)};
}

}  // namespace aerobreak
