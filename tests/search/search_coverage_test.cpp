// The adaptive search's decisions on the seeded synthetic law (docs/ADAPTIVE.md, "Validation"):
// the 95 % intervals cover the true crossings at their nominal rate, the same results in any
// order give the same round, phase I brackets, and groups end as they should.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "tests/support/search_simulation.hpp"

namespace aerobreak::testing {
namespace {

BoundarySearchSpec speed_search() { return testing::speed_search(0.3, 300); }

struct Coverage {
  int covered = 0;
  int searches = 0;
  int converged = 0;
};

// Repeated seeded searches: how often each final interval holds the law's crossing.
std::vector<Coverage> coverage(const BoundarySearchSpec& spec, const SyntheticLaw& law, int searches) {
  std::vector<Coverage> out;
  for (const auto& target : spec.targets)
    for (std::size_t l = 0; l < target.levels.size(); ++l) out.emplace_back();
  for (int s = 0; s < searches; ++s) {
    const auto search = simulate_search(spec, law, 0.001, 1000 + static_cast<std::uint64_t>(s));
    std::size_t e = 0;
    for (const auto& target : spec.targets)
      for (const double level : target.levels) {
        const auto& estimate = search.final.estimates[e];
        const double truth = law.crossing(target.response, level);
        auto& c = out[e++];
        ++c.searches;
        c.converged += search.final.state == GroupState::converged;
        c.covered += estimate.lower && estimate.upper && *estimate.lower <= truth && truth <= *estimate.upper;
      }
  }
  return out;
}

}  // namespace

TEST_CASE("95 % intervals of v50 cover the synthetic law's crossing at the nominal rate", "[search][coverage]") {
  // 1000 seeded searches, each to a relative width of 0.3. Under nominal coverage the count of
  // covering intervals is Binomial(1000, 0.95): mean 950, standard deviation 6.9. Measured with
  // the stopping rule of docs/ADAPTIVE.md (narrow on two consecutive decisions, at least 80
  // results): 948 (94.8 %). Accepted: within two standard deviations, 936 to 964. Stopping the
  // moment the interval first looked narrow gave 930 (93.0 %) on these seeds and fails; so do
  // maximum-likelihood intervals instead of Firth's.
  const auto result = coverage(speed_search(), SyntheticLaw{}, 1000);
  INFO("covered " << result[0].covered << " of " << result[0].searches << ", converged " << result[0].converged);
  CHECK(result[0].converged == 1000);
  CHECK(result[0].covered >= 936);
  CHECK(result[0].covered <= 964);
}

TEST_CASE("Crossings of P(stick) and P(break-up) at 0.1, 0.5 and 0.9 are covered at the nominal rate",
          "[search][coverage]") {
  auto spec = speed_search();
  spec.targets = {{"stick", {0.5}}, {"break-up", {0.1, 0.5, 0.9}}};
  spec.relative_width = 0.4;
  spec.budget = 600;
  spec.batch = 12;
  // 100 searches, four crossings each: Binomial(100, 0.95) has mean 95, sd 2.2; accepted 88-100
  // (three standard deviations). Measured: 93, 98, 91 and 96 (378 of 400, 94.5 %).
  const auto result = coverage(spec, SyntheticLaw{}, 100);
  for (const auto& c : result) {
    INFO("covered " << c.covered << " of " << c.searches << ", converged " << c.converged);
    CHECK(c.converged >= 95);
    CHECK(c.covered >= 88);
  }
}

TEST_CASE("A crossing is found only when narrow on two consecutive decisions, after 80 results", "[search]") {
  auto spec = speed_search();
  spec.relative_width = 0.6;
  SimulatedOutcomes outcomes(SyntheticLaw{}, 0.001, 21);
  const auto candidates = search_candidates(spec);
  const auto results = [&](std::size_t count, int round) {
    std::vector<SearchObservation> observations;
    for (std::size_t k = 0; k < count; ++k) observations.push_back(outcomes.at(candidates[47 + k % 40], round));
    return observations;
  };
  // 200 results over the transition: narrow enough on their own.
  auto observations = results(200, 0);
  const auto confirmed = plan_round(spec, observations, RoundContext{2, 200, 5, 4});
  REQUIRE(confirmed.estimates[0].narrow_enough);
  CHECK(confirmed.estimates[0].found);
  CHECK(confirmed.state == GroupState::converged);
  // The same results, all from the last round: the decision before saw none, so no confirmation.
  for (auto& o : observations) o.round = 1;
  const auto unconfirmed = plan_round(spec, observations, RoundContext{2, 200, 5, 4});
  CHECK(unconfirmed.estimates[0].narrow_enough);
  CHECK_FALSE(unconfirmed.estimates[0].found);
  CHECK(unconfirmed.state == GroupState::searching);
  CHECK(unconfirmed.values.size() == 10);
  // Fewer results than the minimum: no stop, however narrow.
  spec.relative_width = 5.0;
  const auto early = plan_round(spec, results(kMinimumSearchResults - 1, 0), RoundContext{3, 79, 5, 4});
  CHECK(early.estimates[0].narrow_enough);
  CHECK_FALSE(early.estimates[0].found);
  CHECK(early.state == GroupState::searching);
}

TEST_CASE("The same results in any order give the same round", "[search]") {
  const auto spec = speed_search();
  SimulatedOutcomes outcomes(SyntheticLaw{}, 0.001, 77);
  std::vector<SearchObservation> observations;
  for (const double v : {0.005, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.08, 0.1, 0.3, 0.05, 0.04, 0.06})
    observations.push_back(outcomes.at(v, 0));
  const RoundContext context{1, 13, 5, 4};
  const auto plan = plan_round(spec, observations, context);
  REQUIRE(plan.state == GroupState::searching);
  REQUIRE(plan.values.size() == 10);
  std::mt19937 shuffle(3);
  for (int k = 0; k < 5; ++k) {
    std::shuffle(observations.begin(), observations.end(), shuffle);
    const auto again = plan_round(spec, observations, context);
    CHECK(again.values == plan.values);
    CHECK(*again.estimates[0].estimate == *plan.estimates[0].estimate);
  }
}

TEST_CASE("Separated outcomes: the round fills the gap between them (phase I)", "[search]") {
  const auto spec = speed_search();
  const std::vector<SearchObservation> observations{{0.005, "stick"},   {0.01, "stick"},   {0.02, "stick"},
                                                    {0.04, "break-up"}, {0.1, "break-up"}, {0.3, "break-up"}};
  const auto plan = plan_round(spec, observations, RoundContext{1, 6, 1, 0});
  REQUIRE(plan.state == GroupState::searching);
  REQUIRE(plan.values.size() == 10);
  for (std::size_t k = 0; k < plan.values.size(); ++k) {
    CHECK(plan.values[k] > 0.02);
    CHECK(plan.values[k] < 0.04);
    CHECK(plan.reasons[k] == "bracket break-up");
  }
  CHECK(plan.estimates[0].status == "separated");
  CHECK_FALSE(plan.estimates[0].narrow_enough);
}

TEST_CASE("A group ends: converged, budget spent, or its response never seen in the range", "[search]") {
  auto spec = speed_search();
  spec.budget = 20;
  const auto spent = simulate_search(spec, SyntheticLaw{}, 0.001, 9);
  CHECK(spent.final.state == GroupState::budget_spent);
  CHECK(spent.cases == 20);

  const std::vector<SearchObservation> all_stick{{0.005, "stick"}, {0.05, "stick"}, {0.3, "stick"}};
  CHECK(plan_round(speed_search(), all_stick, RoundContext{1, 3, 1, 0}).state == GroupState::out_of_range);

  const auto found = simulate_search(speed_search(), SyntheticLaw{}, 0.001, 11);
  CHECK(found.final.state == GroupState::converged);
  const auto& e = found.final.estimates[0];
  CHECK((*e.upper - *e.lower) / *e.estimate <= 0.3);
}

}  // namespace aerobreak::testing
