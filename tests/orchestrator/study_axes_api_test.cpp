// A study's axes as the API serves them (GET /api/studies/ID: axes; the list and /api/progress
// carry them too; GET /api/cases/ID describes its grid point's axes): pointer, alias, label,
// symbol, unit in the study's system and log scale from the one table of case fields
// (orchestrator/study/field_units.cpp), values for a grid axis and the range for the search's. Each
// answer is checked against its schema in schemas/openapi.json, validated by the project's JSON
// Schema validator. Real HTTP, a real store, worker jobs of the engine's test double.
#include "tests/orchestrator/synthetic_service.hpp"
#include "tests/support/openapi_schema.hpp"

namespace aerobreak::testing {
namespace {

Json response_schema(const Json& description, const std::string& path) {
  return description.at("paths")
      .at(path)
      .at("get")
      .at("responses")
      .at("200")
      .at("content")
      .at("application/json")
      .at("schema");
}

void check_valid(const JsonSchema& schema, const Json& document, const std::string& what) {
  INFO(what << ": " << describe(schema.validate(document)));
  CHECK(schema.validate(document).empty());
}

const Json& axis_named(const Json& axes, const std::string& name) {
  for (const auto& axis : axes)
    if (axis.at("name") == name) return axis;
  FAIL("no axis " << name << " in " << axes.dump());
  throw std::logic_error("unreachable");
}

// The default study (SI) on two speeds and N = 8, with a friction axis (a field without an alias),
// its two walls (a flag) and a classification threshold (a field the table does not describe).
Json physical_grid_study() {
  std::ifstream file(std::string(AEROBREAK_SOURCE_DIR) + "/studies/default.study.json");
  Json study = Json::parse(file);
  study["name"] = "axes of a grid study";
  study["base"]["model"].erase("friction");
  study["base"].erase("classification");
  study["axes"] = {{"impact_speed", {{"values", {8, 12}}}},
                   {"primaries", {{"values", {8}}}},
                   {"/model/friction", {{"values", {0.3}}}},
                   {"/wall/adhesive", {{"values", {true, false}}}},
                   {"/classification/largest_fragment_share", {{"values", {0.9}}}}};
  study["replicates"] = {{"count", 1}, {"seed", 1}};
  return study;
}

// A reduced study searching the speed for every N.
Json reduced_search_study() {
  Json study = small_study("axes of a search", Json::array({0.01}), 1);
  study["base"]["cluster"]["generator"].erase("primaries");
  study["axes"] = {{"primaries", {{"values", {8, 16}}}}};
  study["search"] = {{"axis", "impact_speed"},
                     {"range", {{"from", 0.005}, {"to", 0.3}}},
                     {"relative_width", 0.5},
                     {"budget", 20},
                     {"batch", 10},
                     {"initial", 10}};
  return study;
}

}  // namespace

TEST_CASE("A study's answers describe its axes, grid and search, as schemas/openapi.json says", "[service][axes]") {
  ScratchDirectory scratch("study-axes");
  ServiceProcess service(scratch.path(), synthetic_worker_options());
  const auto grid_id = submit(service, physical_grid_study()).at("id").get<std::int64_t>();
  const auto search_id = submit(service, reduced_search_study()).at("id").get<std::int64_t>();
  const std::string grid_path = "/api/studies/" + std::to_string(grid_id);
  const std::string search_path = "/api/studies/" + std::to_string(search_id);

  const Json grid_axes = service.get(grid_path).at("axes");
  REQUIRE(grid_axes.size() == 5);
  CHECK(grid_axes[0] == Json{{"name", "impact_speed"},
                             {"pointer", "/impact/speed"},
                             {"alias", "impact_speed"},
                             {"label", "impact speed v₀"},
                             {"symbol", "v₀"},
                             {"unit", "m/s"},
                             {"log_scale", true},
                             {"role", "grid"},
                             {"values", {8, 12}},
                             {"range", nullptr}});
  const Json& primaries = axis_named(grid_axes, "primaries");
  CHECK(primaries.at("pointer") == "/cluster/generator/primaries");
  CHECK(primaries.at("symbol") == "N");
  CHECK(primaries.at("unit") == nullptr);  // a count
  CHECK(primaries.at("log_scale") == true);
  const Json& friction = axis_named(grid_axes, "/model/friction");
  CHECK(friction.at("alias") == nullptr);
  CHECK(friction.at("label") == "friction coefficient μ");
  CHECK(friction.at("log_scale") == false);
  const Json& wall = axis_named(grid_axes, "/wall/adhesive");
  CHECK(wall.at("label") == "adhesive wall");
  CHECK(wall.at("unit") == nullptr);
  CHECK(wall.at("values") == Json::array({true, false}));
  const std::string threshold = "/classification/largest_fragment_share";
  const Json& unknown = axis_named(grid_axes, threshold);  // not in the table: its name, no unit
  CHECK(unknown.at("label") == threshold);
  CHECK(unknown.at("symbol") == threshold);
  CHECK(unknown.at("unit") == nullptr);
  CHECK(unknown.at("log_scale") == false);

  const Json search_axes = service.get(search_path).at("axes");
  REQUIRE(search_axes.size() == 2);
  CHECK(search_axes[0].at("name") == "primaries");
  CHECK(search_axes[0].at("values") == Json::array({8, 16}));
  const Json& searched = search_axes[1];
  CHECK(searched.at("name") == "impact_speed");
  CHECK(searched.at("role") == "search");
  CHECK(searched.at("unit") == "d/tau");
  CHECK(searched.at("log_scale") == true);  // the search's scale
  CHECK(searched.at("values") == nullptr);
  CHECK(searched.at("range") == Json::array({0.005, 0.3}));

  // Every answer that carries the axes validates against its description.
  const Json description = openapi();
  const JsonSchema study_schema = openapi_schema(description, response_schema(description, "/api/studies/{id}"));
  for (const auto& path : {grid_path, search_path}) check_valid(study_schema, service.get(path), path);
  for (const std::string list : {"/api/studies", "/api/progress"}) {
    const Json answer = service.get(list);
    CHECK(answer.at("items").size() == 2);
    check_valid(openapi_schema(description, response_schema(description, list)), answer, list);
  }

  // A case describes its grid point's axes, the search's among them, in the case's units.
  for (const auto id : {grid_id, search_id}) REQUIRE(eventually([&] { return study_complete(service, id); }, 120s));
  const JsonSchema axis_schema =
      openapi_schema(description, {{"type", "array"}, {"items", {{"$ref", "#/components/schemas/AxisDescription"}}}});
  for (const auto& [path, speed_unit] : {std::pair{grid_path, "m/s"}, std::pair{search_path, "d/tau"}}) {
    const auto case_id = service.get(path + "/cases?limit=1").at("items").at(0).at("id").get<std::int64_t>();
    const Json detail = service.get("/api/cases/" + std::to_string(case_id));
    check_valid(axis_schema, detail.at("axes"), "case " + std::to_string(case_id));
    std::vector<std::string> names;
    for (const auto& axis : detail.at("axes")) names.push_back(axis.at("name").get<std::string>());
    std::vector<std::string> expected;
    for (const auto& [name, value] : detail.at("grid_point").items()) expected.push_back(name);
    CHECK(names == expected);
    CHECK(axis_named(detail.at("axes"), "impact_speed").at("unit") == speed_unit);
  }
  CHECK(service.kill(SIGTERM) == 0);
}

}  // namespace aerobreak::testing
