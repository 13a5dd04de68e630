#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "orchestrator/cli/outcome_table.hpp"
#include "orchestrator/cli/text_table.hpp"
#include "orchestrator/study/study_units.hpp"

namespace aerobreak::testing {
namespace {

using Json = nlohmann::ordered_json;
using Catch::Matchers::Contains;

Json estimate(double p, double lower, double upper) { return {{"probability", p}, {"ci95", {lower, upper}}}; }

// One grid point of GET /api/studies/ID/outcomes.
Json grid_point(Json axes, int finished, Json stick, Json bounce, Json break_up) {
  return {
      {"grid_point", std::move(axes)},
      {"finished", finished},
      {"failed", 0},
      {"outcomes", {{"stick", stick}, {"bounce", bounce}, {"break-up", break_up}, {"undetermined", {{"count", 0}}}}},
      {"retained_mass_fraction",
       {{"n", finished}, {"mean", 0.25}, {"standard_deviation", 0.1}, {"standard_error", 0.05}, {"ci95", {0.1, 0.4}}}},
      {"fractured_on_wall", 0},
      {"small_strain_exceeded", 0},
      {"small_strain_unchecked", 0}};
}

Json one_point_table() {
  const Json half = estimate(0.5, 0.2, 0.8);
  return {{"grid_points", {grid_point({{"impact_speed", 12.5}}, 4, half, half, half)}}};
}

// The default study's shape: 8 speeds x 2 walls x 2 sizes, 10 replicates, the speed the first axis
// (so that the rows of one wall and size are spread over the list).
Json default_study_table() {
  Json points = Json::array();
  for (const double speed : {4.0, 8.0, 12.0, 16.0, 20.0, 25.0, 30.0, 40.0})
    for (const bool adhesive : {true, false})
      for (const int primaries : {32, 64})
        points.push_back(grid_point({{"impact_speed", speed}, {"/wall/adhesive", adhesive}, {"primaries", primaries}},
                                    10, estimate(1.0, 0.7225, 1.0), estimate(0.0, 0.0, 0.2775),
                                    estimate(0.0, 0.0, 0.2775)));
  return {{"grid_points", points}};
}

std::size_t widest_line(const std::string& text) {
  std::istringstream lines(text);
  std::size_t widest = 0;
  for (std::string line; std::getline(lines, line);) widest = std::max(widest, line.size());
  return widest;
}

}  // namespace

TEST_CASE("A study's speeds are in m/s when it is physical and in d/tau otherwise") {
  CHECK(speed_unit_label(study_unit_system({{"base", {{"units", "physical"}}}})) == "m/s");
  CHECK(speed_unit_label(study_unit_system({{"base", {{"units", "reduced"}}}})) == "d/tau");
  CHECK(speed_unit_label(study_unit_system({{"base", nlohmann::ordered_json::object()}})) == "d/tau");
  CHECK(speed_unit_label(study_unit_system(nlohmann::ordered_json::object())) == "d/tau");
  CHECK(speed_unit_label("mixed") == "m/s where /units = physical, d/tau otherwise");
}

TEST_CASE("The outcome table labels the speed with the study's unit and gives P in % with its interval") {
  const auto physical = format_outcome_table(one_point_table(), "physical");
  INFO(physical);
  CHECK_THAT(physical, Contains("speed") && Contains("m/s") && Contains("12.5") && Contains("50 [20-80]"));
  CHECK_THAT(physical, Contains("speed: the impact speed, in m/s"));
  const auto reduced = format_outcome_table(one_point_table(), "reduced");
  CHECK_THAT(reduced, Contains("d/tau") && !Contains("m/s"));
}

TEST_CASE("The default study's outcome table fits 100 columns: a section per wall and size, a row per speed") {
  const auto text = format_outcome_table(default_study_table(), "physical");
  INFO(text);
  CHECK(widest_line(text) <= 100);
  // One section per value of the other axes, in the order they first come, each with its 8 speeds.
  const auto first = text.find("/wall/adhesive = true, primaries = 32\n");
  const auto second = text.find("/wall/adhesive = true, primaries = 64\n");
  const auto third = text.find("/wall/adhesive = false, primaries = 32\n");
  REQUIRE(first != std::string::npos);
  CHECK(first < second);
  CHECK(second < third);
  CHECK_THAT(text.substr(first, second - first), Contains("\n4 ") && Contains("\n40 "));
  CHECK_THAT(text, Contains("100 [72-100]") && Contains("0 [0-28]"));
  // The legend explains every column, "retained" and "large strain" among them.
  for (const char* term : {"n: ", "stick, bounce, break-up: ", "retained: ", "fractured on wall: ", "large strain: ",
                           "undet.: ", "failed: "})
    CHECK_THAT(text, Contains(term));
}

TEST_CASE("An axis with a unit of its own carries it in the section titles") {
  Json table = one_point_table();
  table["grid_points"][0]["grid_point"] = {
      {"impact_speed", 1.0}, {"/impact/angle", 30}, {"/model/damping/dissipative_time", 0.05}};
  const auto text = format_outcome_table(table, "physical");
  CHECK_THAT(text, Contains("/impact/angle = 30 deg, /model/damping/dissipative_time = 0.05 tau\n"));
}

TEST_CASE("Without a speed axis the first axis makes the rows, with its unit") {
  Json table = one_point_table();
  table["grid_points"][0]["grid_point"] = {{"gamma_over_kn", 0.001}, {"primaries", 64}};
  const auto text = format_outcome_table(table, "reduced");
  INFO(text);
  CHECK_THAT(text, Contains("gamma_over_kn") && Contains("primaries = 64\n"));
  CHECK_THAT(text, !Contains("speed: "));
}

TEST_CASE("A table wider than the page wraps: the columns that do not fit go below, after the key column") {
  TextTable table;
  table.header = {"key", std::string(40, 'a'), std::string(40, 'b'), std::string(40, 'c')};
  table.sections.push_back({"", {{"k1", "1", "2", "3"}, {"k2", "4", "5", "6"}}});
  const auto text = format_text_table(table, 100);
  INFO(text);
  CHECK(widest_line(text) <= 100);
  const auto wrapped = text.find(std::string(40, 'c'));
  REQUIRE(wrapped != std::string::npos);
  // The second block repeats the key column, and its rows follow its own header.
  CHECK(text.find("\nkey", text.find(std::string(40, 'b'))) < wrapped);
  CHECK(text.find("k2", wrapped) != std::string::npos);
  // Wide enough, one block.
  CHECK(format_text_table(table, 200).find(std::string(40, 'c')) < format_text_table(table, 200).find('\n'));
}

TEST_CASE("In a study whose axis sets /units, each section's values carry the unit of its own system") {
  const Json half = estimate(0.5, 0.2, 0.8);
  Json table{{"grid_points",
              {grid_point({{"impact_speed", 10.0}, {"/units", "physical"}, {"/impact/gap", 0.5}}, 4, half, half, half),
               grid_point({{"impact_speed", 0.1}, {"/units", "reduced"}, {"/impact/gap", 0.5}}, 4, half, half, half)}}};
  table["grid_points"][0]["grid_point"]["/material/diameter"] = 2e-8;
  const auto text = format_outcome_table(table, "mixed");
  INFO(text);
  CHECK_THAT(text, Contains("/units = physical, /impact/gap = 0.5 d, /material/diameter = 2e-08 m\n"));
  CHECK_THAT(text, Contains("/units = reduced, /impact/gap = 0.5 d\n"));
  CHECK_THAT(text, Contains("speed: the impact speed, in m/s where /units = physical, d/tau otherwise."));
}

}  // namespace aerobreak::testing
