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
  // 300 seeded searches, each to a relative width of 0.3. Under nominal coverage the count of
  // covering intervals is Binomial(300, 0.95): mean 285, standard deviation 3.8. Measured: 276
  // (92.0 %; at a fixed budget of 60 cases, without the stop on width, 189/200 = 94.5 %): stopping
  // when the interval is first narrow enough ends some groups on a lucky narrow interval
  // (docs/ADAPTIVE.md, "Validation"). Accepted: 267 (89 %) to 297; maximum-likelihood intervals
  // instead of Firth's gave 252 (84 %) and fail.
  const auto result = coverage(speed_search(), SyntheticLaw{}, 300);
  INFO("covered " << result[0].covered << " of " << result[0].searches << ", converged " << result[0].converged);
  CHECK(result[0].converged == 300);
  CHECK(result[0].covered >= 267);
  CHECK(result[0].covered <= 297);
}

TEST_CASE("Crossings of P(stick) and P(break-up) at 0.1, 0.5 and 0.9 are covered at the nominal rate",
          "[search][coverage]") {
  auto spec = speed_search();
  spec.targets = {{"stick", {0.5}}, {"break-up", {0.1, 0.5, 0.9}}};
  spec.relative_width = 0.4;
  spec.budget = 600;
  spec.batch = 12;
  // 100 searches, four crossings each: Binomial(100, 0.95) has mean 95, sd 2.2; accepted 88-100.
  const auto result = coverage(spec, SyntheticLaw{}, 100);
  for (const auto& c : result) {
    INFO("covered " << c.covered << " of " << c.searches << ", converged " << c.converged);
    CHECK(c.converged >= 95);
    CHECK(c.covered >= 88);
  }
}

TEST_CASE("The same results in any order give the same round", "[search]") {
  const auto spec = speed_search();
  SimulatedOutcomes outcomes(SyntheticLaw{}, 0.001, 77);
  std::vector<SearchObservation> observations;
  for (const double v : {0.005, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.08, 0.1, 0.3, 0.05, 0.04, 0.06})
    observations.push_back(outcomes.at(v));
  const auto plan = plan_round(spec, observations, 13, 5);
  REQUIRE(plan.state == GroupState::searching);
  REQUIRE(plan.values.size() == 10);
  std::mt19937 shuffle(3);
  for (int k = 0; k < 5; ++k) {
    std::shuffle(observations.begin(), observations.end(), shuffle);
    const auto again = plan_round(spec, observations, 13, 5);
    CHECK(again.values == plan.values);
    CHECK(*again.estimates[0].estimate == *plan.estimates[0].estimate);
  }
}

TEST_CASE("Separated outcomes: the round fills the gap between them (phase I)", "[search]") {
  const auto spec = speed_search();
  const std::vector<SearchObservation> observations{
      {0.005, "stick"}, {0.01, "stick"}, {0.02, "stick"}, {0.04, "break-up"}, {0.1, "break-up"}, {0.3, "break-up"}};
  const auto plan = plan_round(spec, observations, 6, 1);
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
  CHECK(plan_round(speed_search(), all_stick, 3, 1).state == GroupState::out_of_range);

  const auto found = simulate_search(speed_search(), SyntheticLaw{}, 0.001, 11);
  CHECK(found.final.state == GroupState::converged);
  const auto& e = found.final.estimates[0];
  CHECK((*e.upper - *e.lower) / *e.estimate <= 0.3);
}

}  // namespace aerobreak::testing
