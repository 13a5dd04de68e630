// The units a study and a case are in (orchestrator/study/study_units.hpp): SI for a physical
// base, reduced otherwise, "mixed" when an axis sets the unit system.
#include <catch2/catch.hpp>

#include "orchestrator/study/study_units.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

TEST_CASE("A study's unit system is its base's, reduced by default, mixed when an axis sets it", "[study][units]") {
  CHECK(study_unit_system(Json{{"base", {{"units", "physical"}}}, {"axes", Json::object()}}) == "physical");
  CHECK(study_unit_system(Json{{"base", {{"units", "reduced"}}}}) == "reduced");
  CHECK(study_unit_system(Json{{"base", Json::object()}}) == "reduced");
  CHECK(study_unit_system(Json::object()) == "reduced");
  CHECK(study_unit_system(Json{{"base", {{"units", "physical"}}},
                               {"axes", {{"/units", {{"values", {"reduced", "physical"}}}}}}}) == "mixed");
  CHECK(case_unit_system(Json{{"units", "physical"}}) == "physical");
  CHECK(case_unit_system(Json{{"units", 3}}) == "reduced");
}

TEST_CASE("Each unit system names the unit of each kind of quantity", "[study][units]") {
  const auto si = units_json("physical");
  CHECK(
      si ==
      Json{{"system", "physical"}, {"length", "m"}, {"mass", "kg"}, {"time", "s"}, {"speed", "m/s"}, {"energy", "J"}});
  const auto reduced = units_json("reduced");
  CHECK(reduced.at("speed") == "d/tau");
  CHECK(reduced.at("time") == "tau");
  CHECK(reduced.at("energy") == "k_n d^2");
  const auto mixed = units_json("mixed");
  CHECK(mixed.at("system") == "mixed");
  CHECK(mixed.at("speed").is_null());
}

}  // namespace
}  // namespace aerobreak
