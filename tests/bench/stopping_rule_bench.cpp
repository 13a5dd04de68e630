// A benchmark program, not a test: how often the 95 % interval of v50 holds the truth, and after
// how many cases, under candidate stopping rules of the adaptive search (docs/ADAPTIVE.md,
// "Stopping"), on the seeded synthetic law (tests/support/synthetic_law.hpp). Each seed's search
// runs to the budget without a stop on width (for one crossing the design does not depend on the
// width asked); every rule is then applied to the decisions it went through.
//   build/tests/stopping_rule_bench [SEARCHES] [BUDGET]   (default 1000 searches of 400 cases)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "orchestrator/search/response_fit.hpp"
#include "tests/support/search_simulation.hpp"

namespace {

using namespace aerobreak;
using namespace aerobreak::testing;

constexpr double kZ95 = 1.959963984540054;

// What one decision of a search saw: its cases, the profile interval and the expected half-width.
struct Decision {
  int cases = 0;
  int cases_since_overlap = -1;  // -1: the outcomes do not overlap yet
  std::optional<double> estimate, lower, upper;
  double expected_half_width = INFINITY;  // 1.96 sqrt(E[Var(theta)]), dose units
  bool interval() const { return estimate && lower && upper; }
};

// The decision on these results; its cases_since_overlap is left to the trajectory.
Decision decision_of(const BoundarySearchSpec& spec, std::vector<SearchObservation> observations, std::uint64_t seed) {
  Decision d;
  d.cases = static_cast<int>(observations.size());
  std::sort(observations.begin(), observations.end(), [](const auto& a, const auto& b) {
    return a.value != b.value ? a.value < b.value : a.outcome < b.outcome;
  });
  const auto fit = fit_response(spec, observations, "break-up");
  if (fit.overlap != Overlap::overlapping) return d;
  d.cases_since_overlap = 0;
  const auto found = crossing(spec, fit, 0.5);
  d.estimate = found.estimate, d.lower = found.lower, d.upper = found.upper;
  if (d.estimate) d.expected_half_width = kZ95 * std::sqrt(expected_crossing_variance({&fit, 0.5, 1.0}, seed));
  return d;
}

// The decisions of one search run to the budget.
std::vector<Decision> trajectory(const BoundarySearchSpec& spec, std::uint64_t seed) {
  SimulatedOutcomes outcomes(SyntheticLaw{}, 0.001, seed);
  std::vector<SearchObservation> observations;
  const auto candidates = search_candidates(spec);
  for (const auto index : initial_search_indices(spec)) observations.push_back(outcomes.at(candidates[index], 0));
  std::vector<Decision> out;
  int first_overlap = -1;
  for (int round = 1;; ++round) {
    const auto context = round_context(seed, 0, round, static_cast<int>(observations.size()));
    auto& d = out.emplace_back(decision_of(spec, observations, context.seed));
    if (d.cases_since_overlap >= 0) {
      if (first_overlap < 0) first_overlap = d.cases;
      d.cases_since_overlap = d.cases - first_overlap;
    }
    const auto plan = plan_round(spec, observations, context);
    if (plan.state != GroupState::searching) return out;
    for (const double value : plan.values) observations.push_back(outcomes.at(value, round));
  }
}

bool realised_narrow(const Decision& d, double width) {
  return d.interval() && *d.upper - *d.lower <= width * *d.estimate;
}
// The expected interval as narrow as the search's own check asks (wanted_half_width, dose units).
bool expected_narrow(const Decision& d, double width) {
  if (!d.estimate) return false;
  const auto asked = speed_search(width, 0);
  return d.expected_half_width <= wanted_half_width(asked, search_dose(asked, *d.estimate));
}
bool narrow(const Decision& d, double width) { return realised_narrow(d, width) && expected_narrow(d, width); }

// A rule: whether a search stops at decision k of its trajectory, for a relative width.
using Rule = std::function<bool(const std::vector<Decision>&, std::size_t, double)>;

std::vector<std::pair<std::string, Rule>> rules() {
  const auto last = [](std::size_t count) {
    return [count](const std::vector<Decision>& t, std::size_t k, double w) {
      if (k + 1 < count) return false;
      for (std::size_t j = k + 1 - count; j <= k; ++j)
        if (!narrow(t[j], w)) return false;
      return true;
    };
  };
  const auto with_at_least = [](int cases) {
    return [cases](const std::vector<Decision>& t, std::size_t k, double w) {
      return narrow(t[k], w) && t[k].cases >= cases;
    };
  };
  const auto after_overlap = [](int cases) {
    return [cases](const std::vector<Decision>& t, std::size_t k, double w) {
      return narrow(t[k], w) && t[k].cases_since_overlap >= cases;
    };
  };
  const auto expected_only = [](const std::vector<Decision>& t, std::size_t k, double w) {
    return t[k].interval() && expected_narrow(t[k], w);
  };
  const auto one_more_round = [](const std::vector<Decision>& t, std::size_t k, double w) {
    return k > 0 && narrow(t[k - 1], w) && t[k].interval();
  };
  const auto the_rule = [last](const std::vector<Decision>& t, std::size_t k, double w) {
    return last(2)(t, k, w) && t[k].cases >= static_cast<int>(kMinimumSearchResults);  // no undetermined cases here
  };
  return {
      {"narrow once", last(1)},
      {"expected width only", expected_only},
      {"two consecutive rounds", last(2)},
      {"three consecutive rounds", last(3)},
      {"at least 80 results", with_at_least(80)},
      {"30 cases after overlap", after_overlap(30)},
      {"one more round, any width", one_more_round},
      {"two rounds and 80 results (the rule)", the_rule},
  };
}

void report(const std::vector<std::vector<Decision>>& trajectories, double width, double truth) {
  std::printf("relative width %.2f\n", width);
  for (const auto& [name, rule] : rules()) {
    int stopped = 0, covered = 0;
    double cases = 0.0;
    for (const auto& t : trajectories)
      for (std::size_t k = 0; k < t.size(); ++k)
        if (rule(t, k, width)) {
          ++stopped, cases += t[k].cases;
          covered += *t[k].lower <= truth && truth <= *t[k].upper;
          break;
        }
    const double rate = stopped ? static_cast<double>(covered) / stopped : 0.0;
    std::printf("  %-38s %4d of %4d stopped, covered %5.1f %% (SE %.1f %%), mean cases %5.1f\n", name.c_str(), stopped,
                static_cast<int>(trajectories.size()), 100.0 * rate,
                100.0 * std::sqrt(0.95 * 0.05 / std::max(stopped, 1)), stopped ? cases / stopped : 0.0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int searches = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int budget = argc > 2 ? std::atoi(argv[2]) : 400;
  const auto spec = speed_search(1e-6, budget);  // never narrow: every search runs to the budget
  std::vector<std::vector<Decision>> trajectories;
  for (int s = 0; s < searches; ++s) trajectories.push_back(trajectory(spec, 1000 + static_cast<std::uint64_t>(s)));
  const double truth = SyntheticLaw{}.crossing("break-up", 0.5);
  std::printf("%d seeded searches for v50 = %.3g on the synthetic law, %d cases each at most\n\n", searches, truth,
              budget);
  for (const double width : {0.5, 0.3, 0.2}) report(trajectories, width, truth);
  return 0;
}
