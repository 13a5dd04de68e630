// The units a study and a case are in (orchestrator/study/study_units.hpp): SI for a physical
// base, reduced otherwise, "mixed" when an axis sets the unit system. A study axis as the API
// describes it (field_units.hpp describe_axis), and the scale the correlations' covariates take.
#include <catch2/catch.hpp>

#include <map>
#include <string>

#include "orchestrator/study/field_units.hpp"
#include "orchestrator/study/study_axes.hpp"
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

TEST_CASE("An axis is described by its alias or pointer, in its study's unit system", "[study][units]") {
  const AxisDescription speed = describe_axis("impact_speed", "physical");
  CHECK(speed.pointer == "/impact/speed");
  CHECK(speed.alias == "impact_speed");
  CHECK(speed.label == "impact speed v₀");
  CHECK(speed.symbol == "v₀");
  CHECK(speed.unit == "m/s");
  CHECK(speed.log_scale);
  // The same field named by its pointer: the same description, the alias found.
  const AxisDescription by_pointer = describe_axis("/impact/speed", "reduced");
  CHECK(by_pointer.alias == "impact_speed");
  CHECK(by_pointer.label == speed.label);
  CHECK(by_pointer.unit == "d/tau");
  CHECK(describe_axis("impact_speed", "mixed").unit.empty());                // m/s or d/tau by grid point
  CHECK(describe_axis("/impact/angle", "mixed").unit == "deg");              // the same in both systems
  CHECK(describe_axis("/material/youngs_modulus", "reduced").unit.empty());  // a physical field
  CHECK(describe_axis("/material/youngs_modulus", "physical").unit == "Pa");
  const AxisDescription unknown = describe_axis("/classification/largest_fragment_share", "physical");
  CHECK(unknown.alias.empty());
  CHECK(unknown.label == "/classification/largest_fragment_share");
  CHECK(unknown.symbol == "/classification/largest_fragment_share");
  CHECK(unknown.unit.empty());
  CHECK_FALSE(unknown.log_scale);
  CHECK(describe_axis("generator", "reduced").label == "cluster generator");
  CHECK(describe_axis("/wall/adhesive", "physical").label == "adhesive wall");
}

// The pooled models take gamma/k_n and N in log, D_f and the angle linearly (docs/CORRELATIONS.md):
// the scale of each covariate's field.
TEST_CASE("Each known covariate enters the pooled models in its field's scale", "[study][units]") {
  std::map<std::string, bool> logarithmic;
  for (const auto& field : named_case_fields())
    if (!field.covariate.empty())
      logarithmic[std::string(field.covariate)] = field_log_scale(std::string(field.pointer));
  CHECK(logarithmic ==
        std::map<std::string, bool>{{"gamma_over_kn", true}, {"N", true}, {"Df", false}, {"angle", false}});
}

}  // namespace
}  // namespace aerobreak
