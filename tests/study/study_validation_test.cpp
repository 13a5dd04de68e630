// parse_study refuses a study that breaks its schema, its rules or the submitter's limits, and
// names every offending field by its JSON pointer into the study document.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>

#include "orchestrator/study/field_units.hpp"
#include "orchestrator/study/study_axes.hpp"
#include "orchestrator/study/study_schema_text.hpp"
#include "study_support.hpp"

using namespace aerobreak;
using aerobreak::testing::message_at;
using aerobreak::testing::minimal_study;
using aerobreak::testing::violations_of;
using Catch::Matchers::Contains;
using Json = nlohmann::ordered_json;

TEST_CASE("a valid study parses, completed with the schema's defaults") {
  const Study study = parse_study(minimal_study());
  CHECK(study.name == "test study");
  CHECK(study.case_count() == 2);
  CHECK(study.replicates == 1);
  CHECK(study.seed == 0);
  CHECK(study.max_attempts == 3);
  CHECK(study.case_wall_time == 3600.0);
  CHECK(study.document["replicates"] == Json::parse(R"({"count": 1, "seed": 0})"));
  CHECK(study.document["execution"] == Json::parse(R"({"max_attempts": 3, "case_wall_time": 3600})"));
  REQUIRE(study.axes.size() == 3);
  CHECK(study.axes[0].pointer == "/impact/speed");
  CHECK(study.axes[1].pointer == "/material/gamma_over_kn");
  CHECK(study.axes[2].pointer == "/cluster/generator/primaries");
  CHECK(study.hash.size() == 64);
}

TEST_CASE("schema violations are named by pointer, all at once") {
  Json s = minimal_study();
  s.erase("base");
  s["name"] = "";
  s["replicates"] = {{"count", 0}, {"seed", -1}};
  s["execution"] = {{"case_wall_time", 1e9}};
  const auto v = violations_of(s);
  CHECK(message_at(v, "/base") == "is required");
  CHECK_THAT(message_at(v, "/name"), Contains("at least 1 characters"));
  CHECK_THAT(message_at(v, "/replicates/count"), Contains("must be >= 1"));
  CHECK_THAT(message_at(v, "/replicates/seed"), Contains("must be >= 0"));
  CHECK_THAT(message_at(v, "/execution/case_wall_time"), Contains("must be <= 604800"));
}

TEST_CASE("bad ranges are named by pointer") {
  Json s = minimal_study();
  s["axes"]["gamma_over_kn"] = {{"log", {{"from", 0.0}, {"to", 1e-2}, {"count", 3}}}};
  s["axes"]["impact_speed"] = {{"linear", {{"from", 0.01}, {"to", 0.02}, {"count", 0}}}};
  s["axes"]["/model/friction"] = {{"values", Json::array()}};
  s["axes"]["/impact/angle"] = {{"values", {0}}, {"linear", {{"from", 0}, {"to", 10}, {"count", 2}}}};
  const auto v = violations_of(s);
  CHECK_THAT(message_at(v, "/axes/gamma_over_kn/log/from"), Contains("must be > 0"));
  CHECK_THAT(message_at(v, "/axes/impact_speed/linear/count"), Contains("must be >= 1"));
  CHECK_THAT(message_at(v, "/axes/~1model~1friction/values"), Contains("at least 1 items"));
  CHECK_THAT(message_at(v, "/axes/~1impact~1angle"),
             Contains("must match exactly one of 3 alternatives, matches 1 and 2"));
}

TEST_CASE("a range of one value needs from = to, and a longer one distinct ends") {
  Json s = minimal_study();
  s["axes"]["impact_speed"] = {{"linear", {{"from", 0.01}, {"to", 0.02}, {"count", 1}}}};
  CHECK_THAT(message_at(violations_of(s), "/axes/impact_speed/linear/count"),
             Contains("at least 2 when from and to differ"));
  s["axes"]["impact_speed"] = {{"log", {{"from", 0.01}, {"to", 0.01}, {"count", 3}}}};
  CHECK_THAT(message_at(violations_of(s), "/axes/impact_speed/log/count"), Contains("must be 1 when from = to"));
  s["axes"]["impact_speed"] = {{"log", {{"from", 0.01}, {"to", 0.01}, {"count", 1}}}};
  CHECK(parse_study(s).case_count() == 1);
}

TEST_CASE("an axis name is an alias or a JSON pointer into the case") {
  Json s = minimal_study();
  s["axes"]["speed"] = {{"values", {1}}};
  s["axes"]["/bad~2pointer"] = {{"values", {1}}};
  s["axes"]["/name"] = {{"values", {"a"}}};
  const auto v = violations_of(s);
  CHECK_THAT(message_at(v, "/axes/speed"),
             Contains("neither an axis alias (impact_speed, gamma_over_kn, primaries, generator, fractal_dimension, "
                      "prefactor, geometric_standard_deviation)"));
  CHECK_THAT(message_at(v, "/axes/~1bad~02pointer"), Contains("not a valid JSON pointer"));
  CHECK_THAT(message_at(v, "/axes/~1name"), Contains("is a label"));
}

TEST_CASE("the named case fields: the schema's axis aliases, each number with a unit entry") {
  const Json schema = Json::parse(study_schema_text());
  std::vector<std::string> schema_aliases, table_aliases, covariates;
  for (const auto& [name, spec] : schema["properties"]["axes"]["properties"].items()) schema_aliases.push_back(name);
  for (const auto& field : named_case_fields()) {
    INFO(field.name);
    // field_units.cpp lists each number's unit; the generator's method is a name, without one.
    if (field.name != "generator") CHECK(exported_axis_unit(std::string(field.pointer), false) != "unknown");
    if (field.axis_alias) {
      table_aliases.emplace_back(field.name);
      CHECK(axis_pointer(std::string(field.name)) == field.pointer);
      // The schema's description says where it points.
      CHECK_THAT(schema["properties"]["axes"]["properties"][std::string(field.name)]["description"].get<std::string>(),
                 Contains("Alias of " + std::string(field.pointer)));
    }
    if (!field.covariate.empty()) covariates.emplace_back(field.covariate);
  }
  CHECK(table_aliases == schema_aliases);
  CHECK(covariates == std::vector<std::string>{"gamma_over_kn", "N", "Df", "angle"});
  CHECK(known_covariate_names() == "gamma_over_kn, N, Df, angle");
  CHECK(axis_pointer("angle").empty());  // a covariate's name only, not an axis alias
}

TEST_CASE("a study has 1 to 8 axes, no two setting the same field") {
  Json s = minimal_study();
  s["axes"] = Json::object();
  CHECK(message_at(violations_of(s), "/axes") == "must name at least 1 axis");

  s = minimal_study();
  for (const char* name : {"/model/friction", "/impact/angle", "/impact/gap", "/run/steps_per_period",
                           "/model/twisting", "/wall/adhesive"})
    s["axes"][name] = {{"values", {1}}};
  CHECK(message_at(violations_of(s), "/axes") == "must name at most 8 axes (got 9)");

  s = minimal_study();
  s["axes"]["/impact/speed"] = {{"values", {0.03}}};
  s["axes"]["/material"] = {{"values", {1}}};
  const auto v = violations_of(s);
  CHECK_THAT(message_at(v, "/axes/~1impact~1speed"), Contains("the same case field as axis \"impact_speed\""));
  CHECK_THAT(message_at(v, "/axes/~1material"), Contains("overlapping that of axis \"gamma_over_kn\""));
}

TEST_CASE("too many cases are refused before anything is expanded, with the count and the limit") {
  Json s = minimal_study();
  s["axes"]["impact_speed"] = {{"linear", {{"from", 0.01}, {"to", 0.02}, {"count", 10000}}}};
  s["axes"]["gamma_over_kn"] = {{"log", {{"from", 1e-4}, {"to", 1e-2}, {"count", 10000}}}};
  s["replicates"] = {{"count", 3}};
  // Every case would be invalid (no run section): only the count is reported, so nothing was expanded.
  s["base"].erase("run");
  const auto start = std::chrono::steady_clock::now();
  const auto v = violations_of(s);
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));
  REQUIRE(v.size() == 1);
  CHECK(v[0].pointer == "/axes");
  CHECK(v[0].message ==
        "expands to 10000 x 10000 x 1 x 3 replicates = 300000000 cases (axis sizes x replicates); the limit here is "
        "100000 cases");

  for (const char* name :
       {"/model/friction", "/impact/angle", "/impact/gap", "/run/steps_per_period", "/model/restitution_x"})
    s["axes"][name] = {{"linear", {{"from", 1}, {"to", 2}, {"count", 10000}}}};
  CHECK_THAT(message_at(violations_of(s), "/axes"), Contains("= more than 18446744073709551615 cases"));

  StudyLimits tight;
  tight.max_cases = 1;
  CHECK_THAT(
      message_at(violations_of(minimal_study(), tight), "/axes"),
      Contains("expands to 2 x 1 x 1 x 1 replicate = 2 cases (axis sizes x replicates); the limit here is 1 cases"));
}

TEST_CASE("a case that becomes invalid after substitution is named with its grid point and replicate") {
  Json s = minimal_study();
  s["base"]["model"] = {{"rolling", {{"enabled", true}, {"critical_displacement", 0.01}}}};
  s["axes"]["/model/normal"] = {{"values", {"jkr", "hertz"}}};
  s["replicates"] = {{"count", 2}};
  const auto v = violations_of(s);
  REQUIRE(v.size() == 1);
  CHECK(v[0].pointer == "/base/model/rolling/enabled");
  CHECK_THAT(v[0].message, Contains("rolling resistance needs an adhesive normal law"));
  CHECK_THAT(v[0].message, Contains("in case impact_speed=0.01 gamma_over_kn=0.001 primaries=8 /model/normal=hertz, "
                                    "replicate 0 and 3 other cases"));
}

TEST_CASE("a swept value that makes a case invalid is named at its axis") {
  Json s = minimal_study();
  s["axes"]["impact_speed"] = {{"values", {0.01, -0.02}}};
  s["axes"]["/model/friction"] = {{"values", {"high"}}};
  const auto v = violations_of(s);
  CHECK_THAT(message_at(v, "/axes/impact_speed"), Contains("must be > 0 (got -0.02) (in case impact_speed=-0.02"));
  CHECK_THAT(message_at(v, "/axes/~1model~1friction"), Contains("must be a number (got string \"high\")"));
}

TEST_CASE("the base sets neither a swept field nor a seed the replicates derive") {
  Json s = minimal_study();
  s["base"]["impact"] = {{"speed", 0.05}, {"orientation_seed", 4}};
  s["base"]["cluster"]["generator"]["seed"] = 7;
  auto v = violations_of(s);
  CHECK_THAT(message_at(v, "/base/impact/speed"), Contains("is set by axis \"impact_speed\""));
  CHECK_THAT(message_at(v, "/base/impact/orientation_seed"), Contains("derived for each replicate"));
  CHECK_THAT(message_at(v, "/base/cluster/generator/seed"), Contains("derived for each replicate"));

  // Sweeping a seed is the way to choose it; the base then leaves it out too.
  s["base"]["impact"].erase("speed");
  s["base"]["impact"].erase("orientation_seed");
  s["base"]["cluster"]["generator"].erase("seed");
  s["axes"]["/cluster/generator/seed"] = {{"values", {7}}};
  CHECK(parse_study(s).case_count() == 2);
}

TEST_CASE("an axis repeating a value is refused: it would run the same case twice") {
  Json s = minimal_study();
  s["axes"]["primaries"] = {{"values", {8, 8.0}}};
  CHECK_THAT(message_at(violations_of(s), "/axes/primaries"), Contains("repeats the value 8 (values 0 and 1)"));
}

TEST_CASE("primaries are counts: non-integral values are refused") {
  Json s = minimal_study();
  s["axes"]["primaries"] = {{"values", {8, 8.5, "9"}}};
  auto v = violations_of(s);
  CHECK_THAT(message_at(v, "/axes/primaries/values/1"), Contains("must be an integer"));
  CHECK_THAT(message_at(v, "/axes/primaries/values/2"), Contains("must be an integer"));
  s["axes"]["primaries"] = {{"linear", {{"from", 16}, {"to", 32}, {"count", 4}}}};
  CHECK_THAT(message_at(violations_of(s), "/axes/primaries/linear"), Contains("gives 21.33333"));
}

TEST_CASE("more primaries per case than the limit are refused") {
  Json s = minimal_study();
  s["axes"]["primaries"] = {{"values", {8, 5000}}};
  StudyLimits limits;
  limits.max_primaries = 4096;
  CHECK(message_at(violations_of(s, limits), "/axes/primaries") ==
        "asks for 5000 primaries; the limit here is 4096 per case");

  s["axes"].erase("primaries");
  s["base"]["cluster"]["generator"]["primaries"] = 4097;
  CHECK_THAT(message_at(violations_of(s, limits), "/base/cluster/generator/primaries"),
             Contains("asks for 4097 primaries"));
}

TEST_CASE("cluster files are refused where the submitter may not name files, before any is read") {
  Json s = minimal_study();
  s["axes"].erase("primaries");
  s["base"]["cluster"] = {{"file", {{"path", "/etc/shadow"}}}};
  StudyLimits http;
  http.allow_cluster_files = false;
  auto v = violations_of(s, http);
  REQUIRE(v.size() == 1);
  CHECK(v[0].pointer == "/base/cluster/file");
  CHECK_THAT(v[0].message, Contains("cluster files are not accepted here"));

  s["base"]["cluster"] = {{"generator", Json::object()}};
  s["axes"]["primaries"] = {{"values", {8}}};
  s["axes"]["/cluster/file/path"] = {{"values", {"/etc/passwd"}}};
  CHECK_THAT(message_at(violations_of(s, http), "/axes/~1cluster~1file~1path"), Contains("not accepted here"));
}

TEST_CASE("relative cluster file paths are made absolute against the study's directory") {
  const aerobreak::testing::ScratchDirectory scratch("paths");
  scratch.write("rod.xyz", aerobreak::testing::kRodXyz);
  Json s = minimal_study();
  s["axes"].erase("primaries");
  s["base"]["cluster"] = {{"file", {{"path", "rod.xyz"}}}};
  const Study study = parse_study(s, {}, scratch.path());
  const std::string resolved = (scratch.path() / "rod.xyz").string();
  CHECK(study.document["base"]["cluster"]["file"]["path"] == resolved);
  CHECK(study.cases[0].document["cluster"]["file"]["path"] == resolved);

  const auto v = violations_of(s, {}, scratch.path() / "elsewhere");
  CHECK_THAT(message_at(v, "/base/cluster/file/path"),
             Contains("no such file: " + (scratch.path() / "elsewhere/rod.xyz").string()));
}

TEST_CASE("load_study names a file that is missing or not JSON") {
  const aerobreak::testing::ScratchDirectory scratch("load");
  try {
    load_study(scratch.write("broken.json", "{\"name\": "));
    FAIL("accepted a file that is not JSON");
  } catch (const StudyError& e) {
    REQUIRE(e.violations().size() == 1);
    CHECK(e.violations()[0].pointer.empty());
    CHECK_THAT(e.violations()[0].message, Contains("broken.json is not valid JSON: [json.exception.parse_error"));
  }
  CHECK_THROWS_WITH(load_study(scratch.path() / "absent.json"), Contains("cannot open study file"));
}

TEST_CASE("the study schema file is the one compiled in") {
  std::ifstream in(aerobreak::testing::source_path("schemas/study.schema.json"));
  CHECK(study_schema().schema() == Json::parse(in));
}

namespace {

// The default study (physical units) at two speeds, one wall, one size and one replicate.
Json small_physical_study() {
  std::ifstream in(aerobreak::testing::source_path("studies/default.study.json"));
  Json s = Json::parse(in);
  s["axes"] = {{"impact_speed", {{"values", {4, 8}}}}, {"primaries", {{"values", {32}}}}};
  s["replicates"] = {{"count", 1}, {"seed", 1}};
  return s;
}

std::size_t count_at(const std::vector<SchemaViolation>& violations, const std::string& pointer) {
  return static_cast<std::size_t>(std::count_if(violations.begin(), violations.end(),
                                                [&](const SchemaViolation& v) { return v.pointer == pointer; }));
}

}  // namespace

TEST_CASE("every problem of a study comes in one answer: a replicate count does not hide the cases' errors") {
  REQUIRE_NOTHROW(parse_study(small_physical_study()));
  Json s = small_physical_study();
  s["replicates"]["count"] = 0;
  s["base"]["material"]["poisson_ratio"] = 0.7;
  s["base"]["material"]["density"] = 1.725;  // g/cm^3 for kg/m^3
  const auto v = violations_of(s);
  INFO(describe(v));
  CHECK_THAT(message_at(v, "/replicates/count"), Contains("must be >= 1 (got 0)"));
  CHECK_THAT(message_at(v, "/base/material/poisson_ratio"), Contains("must be < 0.5 (got 0.7) (in every case)"));
  CHECK_THAT(message_at(v, "/base/material/density"),
             Contains("must be >= 100 (got 1.725); in kg/m^3: 1.7 g/cm^3 is 1700 (in every case)"));
  CHECK(v.size() == 3);
}

TEST_CASE("a study whose material is in SI without \"units\" is told to add it, and checked as it meant") {
  Json s = small_physical_study();
  s["base"].erase("units");
  auto v = violations_of(s);
  INFO(describe(v));
  REQUIRE(v.size() == 1);
  CHECK(v[0].pointer == "/base/units");
  CHECK_THAT(v[0].message, Contains("is missing, so the case is in reduced units") &&
                               Contains("add \"units\": \"physical\"") && Contains("(in every case)"));

  s["base"]["material"]["diameter"] = -1;  // a problem of the case as it meant it comes too
  v = violations_of(s);
  CHECK(count_at(v, "/base/units") == 1);
  CHECK_THAT(message_at(v, "/base/material/diameter"), Contains("must be >= 1e-09 (got -1)"));

  Json reduced = minimal_study();
  reduced["base"]["units"] = "physical";
  CHECK_THAT(message_at(violations_of(reduced), "/base/units"), Contains("this /material is reduced (gamma_over_kn)"));
}

TEST_CASE("a 20 m primary diameter is blamed on the diameter, not on the impact speed") {
  Json s = small_physical_study();
  s["base"]["material"]["diameter"] = 20;  // 20 nm meant
  const auto v = violations_of(s);
  INFO(describe(v));
  REQUIRE(v.size() == 1);
  CHECK(v[0].pointer == "/base/material/diameter");
  CHECK_THAT(v[0].message, Contains("must be <= 0.001 (got 20); in m: 20 nm is 2e-08 (in every case)"));
}

TEST_CASE("a physical speed too slow to reach the wall in time is told in m/s and seconds") {
  Json s = small_physical_study();
  s["axes"]["impact_speed"] = {{"values", {1e-4, 8}}};
  const auto v = violations_of(s);
  INFO(describe(v));
  REQUIRE(v.size() == 1);
  CHECK(v[0].pointer == "/axes/impact_speed");
  // gap 0.01 d = 2e-10 m at 1e-4 m/s: 2e-06 s, beyond the 3e-07 s limit.
  CHECK_THAT(v[0].message, Contains("at 0.0001 m/s the cluster would reach the wall after 2e-06 s (the gap, 0.01 d = "
                                    "2e-10 m, over the normal speed), beyond /run/time_limit_s (3e-07 s)"));
}
