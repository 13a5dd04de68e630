#include <catch2/catch.hpp>

#include <string>

#include "orchestrator/cli/outcome_table.hpp"

namespace aerobreak::testing {
namespace {

// One grid point of GET /api/studies/ID/outcomes, enough for the table.
nlohmann::ordered_json one_point_table() {
  const nlohmann::ordered_json estimate{{"probability", 0.5}, {"ci95", {0.2, 0.8}}};
  return {{"grid_points",
           {{{"grid_point", {{"impact_speed", 12.5}}},
             {"finished", 4},
             {"failed", 0},
             {"outcomes", {{"stick", estimate}, {"bounce", estimate}, {"break-up", estimate}, {"undetermined", {{"count", 0}}}}},
             {"retained_mass_fraction_mean", 0.25},
             {"fractured_on_wall", 0},
             {"small_strain_exceeded", 0},
             {"small_strain_unchecked", 0}}}}};
}

}  // namespace

TEST_CASE("A study's speeds are in m/s when it is physical and in d/tau otherwise") {
  CHECK(speed_unit_label({{"base", {{"units", "physical"}}}}) == "m/s");
  CHECK(speed_unit_label({{"base", {{"units", "reduced"}}}}) == "d/tau");
  CHECK(speed_unit_label({{"base", nlohmann::ordered_json::object()}}) == "d/tau");
  CHECK(speed_unit_label(nlohmann::ordered_json::object()) == "d/tau");
}

TEST_CASE("The outcome table labels the impact-speed column with its unit") {
  const auto labelled = format_outcome_table(one_point_table(), "m/s");
  CHECK_THAT(labelled, Catch::Contains("impact_speed (m/s)") && Catch::Contains("12.5") &&
                           Catch::Contains("0.50 [0.20, 0.80]"));
  CHECK_THAT(format_outcome_table(one_point_table()), !Catch::Contains("(m/s)"));
}

}  // namespace aerobreak::testing
