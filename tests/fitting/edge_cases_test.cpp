// The whole correlation set on studies built to be awkward: separated outcomes, a one-point grid,
// grid points whose cases are all undetermined, a study without a transition; and the fragment-size
// laws on sizes drawn from a known power law.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "engine/impact/json_schema.hpp"
#include "orchestrator/fitting/correlation_json.hpp"
#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/fitting/fragment_sizes.hpp"
#include "tests/fitting/synthetic_study.hpp"

namespace aerobreak {
namespace {

// `outcomes` per speed: one string of s (stick), b (bounce), u (break-up), ? (undetermined).
CaseOutcomeTable study_of(const std::vector<double>& speeds, const std::vector<std::string>& outcomes) {
  CaseOutcomeTable table;
  table.axes = {"impact_speed"};
  for (std::size_t g = 0; g < speeds.size(); ++g) {
    table.grid_points.push_back({{"impact_speed", speeds[g]}});
    for (const char letter : outcomes[g]) {
      CaseOutcome c;
      c.grid_point = g;
      c.outcome = letter == 's'   ? ImpactOutcome::stick
                  : letter == 'b' ? ImpactOutcome::bounce
                  : letter == 'u' ? ImpactOutcome::break_up
                                  : ImpactOutcome::undetermined;
      c.retained_mass_fraction = c.outcome == ImpactOutcome::stick ? 1.0 : 0.5;
      table.cases.push_back(c);
    }
  }
  return table;
}

CorrelationSet correlations_of(const CaseOutcomeTable& table) {
  CorrelationRequest request;
  request.speed_axis = "impact_speed";
  return compute_correlations(table, request, {7, std::string(64, 'a'), 1, "test"});
}

// The summary and every document of the set are valid against schemas/correlation.schema.json,
// whatever their fits' status.
void check_documents_against_schema(const CorrelationSet& set) {
  std::ifstream file(std::string(AEROBREAK_SOURCE_DIR) + "/schemas/correlation.schema.json");
  REQUIRE(file);
  const JsonSchema schema(nlohmann::ordered_json::parse(file));
  INFO(describe(schema.validate(correlation_summary_json(set))));
  CHECK(schema.validate(correlation_summary_json(set)).empty());
  for (const auto& name : fit_names(set)) {
    const auto document = *fit_json(set, name);
    INFO(name << ": " << describe(schema.validate(document)));
    CHECK(schema.validate(document).empty());
  }
}

const LogisticFit& logistic_named(const CorrelationSet& set, const std::string& name) {
  for (const auto& fit : set.logistic)
    if (fit.common.name == name) return fit;
  FAIL("no fit " << name);
  throw;
}

}  // namespace

TEST_CASE("Complete separation: Firth's estimate, a bounded v50 inside the bracket, no infinite number",
          "[fitting][separation]") {
  const auto set = correlations_of(study_of({0.01, 0.02, 0.04, 0.08}, {"sssss", "sssss", "uuuuu", "uuuuu"}));
  const LogisticFit& fit = logistic_named(set, "break-up.speed.g1");
  CHECK(fit.common.status == FitStatus::separation);
  CHECK(fit.separation_complete);
  CHECK(fit.method == "Firth penalised likelihood");
  REQUIRE(fit.separation_bracket);
  CHECK((*fit.separation_bracket)[0] == 0.02);
  CHECK((*fit.separation_bracket)[1] == 0.04);
  CHECK(fit.common.coefficients.allFinite());
  const CriticalValue& v50 = fit.critical[1];
  REQUIRE(v50.estimate);
  REQUIRE(v50.lower);
  REQUIRE(v50.upper);
  CHECK(*v50.estimate > 0.02);
  CHECK(*v50.estimate < 0.04);
  CHECK(*v50.lower < *v50.estimate);
  CHECK(*v50.upper > *v50.estimate);
  CHECK(*v50.upper < 1.0);  // bounded within the searched range, not at its end
  // The JSON holds no infinity or NaN (they would not survive dump/parse as numbers).
  const auto json = fit_json(set, fit.common.name);
  REQUIRE(json);
  CHECK(nlohmann::json::parse(json->dump()).at("separation").at("complete") == true);
  check_documents_against_schema(set);
}

TEST_CASE("Quasi-complete separation is reported as such, with a bounded v50", "[fitting][separation]") {
  const auto set = correlations_of(study_of({0.01, 0.02, 0.04, 0.08}, {"sssss", "ssuuu", "uuuuu", "uuuuu"}));
  const LogisticFit& fit = logistic_named(set, "break-up.speed.g1");
  CHECK(fit.common.status == FitStatus::separation);
  CHECK_FALSE(fit.separation_complete);
  CHECK(fit.perfectly_predicted == 3);
  REQUIRE(fit.critical[1].lower);
  REQUIRE(fit.critical[1].upper);
  CHECK(*fit.critical[1].lower >= 0.005);
  CHECK(*fit.critical[1].upper <= 0.08);
  check_documents_against_schema(set);
}

TEST_CASE("A one-point grid says it has too few points, for every fit", "[fitting][edge]") {
  const auto set = correlations_of(study_of({0.05}, {"ssuuu"}));
  REQUIRE(set.grid_points.size() == 1);
  CHECK(set.grid_points[0].probabilities[2]->probability == Approx(0.6));
  for (const auto& fit : set.logistic) {
    CHECK(fit.common.status == FitStatus::insufficient_data);
    CHECK(fit.common.coefficients.size() == 0);
  }
  REQUIRE_FALSE(set.retained_fraction.empty());
  CHECK(set.retained_fraction[0].common.status == FitStatus::insufficient_data);
  CHECK(logistic_named(set, "break-up.speed.g1").common.detail.find("too few points") != std::string::npos);
  check_documents_against_schema(set);
}

TEST_CASE("Grid points whose cases are all undetermined are counted, left out of the fits, and never guessed",
          "[fitting][edge]") {
  const auto set =
      correlations_of(study_of({0.01, 0.02, 0.04, 0.08, 0.16}, {"sssss", "sssus", "?????", "uusuu", "uuuuu"}));
  const GridPointSummary& unknown = set.grid_points[2];
  CHECK(unknown.cases == 5);
  CHECK(unknown.undetermined == 5);
  CHECK(unknown.determined() == 0);
  CHECK_FALSE(unknown.probabilities[0]);
  CHECK_FALSE(unknown.retained_mass_fraction);
  const LogisticFit& fit = logistic_named(set, "break-up.speed.g1");
  CHECK(fit.common.status == FitStatus::ok);
  CHECK(fit.common.cases == 20);
  CHECK(fit.common.groups == 4);
  const auto json = grid_points_json(set);
  CHECK(json.at("grid_points")[2].at("outcomes").at("stick").at("probability").is_null());
  CHECK(fit_json(set, "grid-points") == json);
  check_documents_against_schema(set);
}

TEST_CASE("A study that is all undetermined, or has no transition, fits nothing and says why", "[fitting][edge]") {
  const auto undetermined = correlations_of(study_of({0.01, 0.02}, {"???", "???"}));
  CHECK(undetermined.logistic.empty());  // no outcome occurs: nothing to model
  const auto all_stick = correlations_of(study_of({0.01, 0.02, 0.04}, {"sss", "sss", "sss"}));
  const LogisticFit& stick = logistic_named(all_stick, "stick.speed.g1");
  CHECK(stick.common.status == FitStatus::no_transition);
  CHECK(stick.common.detail.find("only stick") != std::string::npos);
  REQUIRE(stick.common.validity.size() == 1);
  CHECK(stick.common.validity[0].min == 0.01);
  CHECK(stick.common.validity[0].max == 0.04);
  check_documents_against_schema(undetermined);
  check_documents_against_schema(all_stick);
}

TEST_CASE("Fragment sizes drawn from a power law give back its exponent, and the lognormal loses Vuong's test",
          "[fitting][fragments]") {
  // tau = 2 on 1..1000, drawn by inverting the cumulative distribution.
  constexpr std::int64_t kLargest = 1000;
  std::vector<double> cdf;
  double norm = 0.0;
  for (std::int64_t s = 1; s <= kLargest; ++s) norm += std::pow(double(s), -2.0);
  double sum = 0.0;
  for (std::int64_t s = 1; s <= kLargest; ++s) cdf.push_back(sum += std::pow(double(s), -2.0) / norm);
  synthetic::Uniform uniform(42);
  std::vector<std::int64_t> sizes;
  for (int i = 0; i < 4000; ++i) sizes.push_back(std::lower_bound(cdf.begin(), cdf.end(), uniform()) - cdf.begin() + 1);
  const FragmentSizeFit fit = fit_fragment_sizes(sizes, kLargest);
  REQUIRE(fit.common.status == FitStatus::ok);
  // Within three standard errors of the truth.
  CHECK(std::abs(fit.exponent - 2.0) < 3.0 * fit.exponent_standard_error);
  CHECK(fit.exponent_standard_error < 0.05);
  CHECK(fit.power_law_ks < 0.03);
  CHECK(fit.vuong_statistic < 0.0);
  CHECK(fit.power_law_log_likelihood > fit.lognormal_log_likelihood);
}

}  // namespace aerobreak

namespace aerobreak {

// The measured crossing (observed_crossing, served with each group's fit in impact speed, which the
// dashboard and studies/analysis/transition_fit.py read): linear in log dose between the two points
// around the level, the first crossing, a point on the level itself, none when the level is never
// crossed.
TEST_CASE("The measured crossing of a level: linear in log dose between the points around it", "[fitting][crossing]") {
  const std::vector<std::pair<double, double>> rising{{0.01, 0.0}, {0.02, 0.25}, {0.04, 0.75}, {0.08, 1.0}};
  CHECK(*observed_crossing(rising, 0.5) == Approx(std::sqrt(0.02 * 0.04)).epsilon(1e-12));  // halfway in log
  CHECK(*observed_crossing(rising, 0.25) == Approx(0.02).epsilon(1e-12));
  const std::vector<std::pair<double, double>> falling{{1.0, 1.0}, {10.0, 0.0}};
  CHECK(*observed_crossing(falling, 0.9) == Approx(std::pow(10.0, 0.1)).epsilon(1e-12));
  CHECK_FALSE(observed_crossing({{1.0, 0.0}, {2.0, 0.3}}, 0.5));
  CHECK_FALSE(observed_crossing({{1.0, 0.5}}, 0.5));  // one point: nothing to interpolate
}

}  // namespace aerobreak
