// Case files against schemas/case.schema.json: valid examples load with their defaults completed,
// invalid ones fail with errors that name the field by its JSON pointer; physical units convert
// so that lambda (eq 19) is kept.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <unistd.h>

#include "engine/core/units.hpp"
#include "engine/impact/impact_case.hpp"
#include "engine/impact/json_schema.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

namespace {

// The violations of a case that must be rejected.
std::vector<SchemaViolation> rejection(const Json& document) {
  try {
    parse_impact_case(document);
  } catch (const CaseError& e) {
    return e.violations();
  }
  FAIL("the case was accepted: " << document.dump());
  return {};
}

bool names(const std::vector<SchemaViolation>& violations, const std::string& pointer, const std::string& words = "") {
  for (const auto& v : violations)
    if (v.pointer == pointer && v.message.find(words) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("a minimal case loads and the schema's defaults are completed") {
  const ImpactCase c = parse_impact_case(testing::minimal_case());
  CHECK(c.document["units"] == "reduced");
  CHECK(c.document["model"]["friction"] == 0.5);
  CHECK(c.document["model"]["damping"]["law"] == "none");
  CHECK(c.document["wall"]["adhesive"] == true);
  CHECK(c.document["classification"]["largest_fragment_share"] == 0.9);
  CHECK(c.document["run"]["settle"]["rest_speed_fraction"] == 0.01);
  CHECK(c.document["cluster"]["generator"]["method"] == "ballistic");
  CHECK(c.model.normal == NormalLaw::jkr);
  CHECK(c.model.friction == 0.5);
  CHECK(c.thresholds.bounce_share == 0.9);
  CHECK(c.angle_degrees == 0.0);
  CHECK(c.gap == 0.01);
  CHECK(c.cluster.generator.primaries == 8);
  CHECK(c.cluster.relax);
  CHECK(c.material.surface_energy == 0.01);
  CHECK_THAT(normal_stiffness(c.material, 1.0), WithinRel(1.0, 1e-14));  // reduced units: k_n = 1
  CHECK(c.wall_material.surface_energy == c.material.surface_energy);
}

TEST_CASE("the study cases of figure 4 are valid cases") {
  for (const char* name : {"studies/figure4_impact.case.json", "studies/figure4_impact_n256.case.json"}) {
    INFO(name);
    const ImpactCase c = load_impact_case(testing::source_path(name));
    CHECK(c.model.friction == 0.5);
    CHECK(c.material.surface_energy == 0.001);
    CHECK_FALSE(c.wall_adhesive);
    // The report's speed 1 d/tau_g with k_n = 2e5 m g/d is 1/sqrt(2e5) d/tau in our units.
    CHECK_THAT(c.speed, WithinRel(1.0 / std::sqrt(2e5), 1e-12));
    // lambda of eq 19 in the report's units: 5.7855 (gamma/k_n)^(2/3) gamma d^2/(m v^2) with
    // gamma = 0.001 x 2e5 m g/d and v = sqrt(g d): 5.7855 x 0.01 x 200 = 11.57.
    const double constant = std::pow(3.0 * std::numbers::pi, 5.0 / 3.0) / (4.0 * std::cbrt(6.0));
    CHECK_THAT(adhesion_energy_ratio(c.material, 1.0, c.speed), WithinRel(constant * 0.01 * 200.0, 1e-9));
  }
  CHECK(load_impact_case(testing::source_path("studies/figure4_impact.case.json")).cluster.generator.primaries == 4096);
  CHECK(load_impact_case(testing::source_path("studies/figure4_impact_n256.case.json")).cluster.generator.primaries ==
        256);
}

TEST_CASE("invalid cases are rejected with errors that name the field") {
  Json c = testing::minimal_case();

  SECTION("a value out of range") {
    c["model"] = {{"friction", -1.0}};
    const auto v = rejection(c);
    CHECK(names(v, "/model/friction", "must be >= 0"));
    CHECK_THAT(describe(v), Contains("/model/friction: must be >= 0 (got -1)"));
  }
  SECTION("a misspelt field") {
    c["model"] = {{"frcition", 0.3}};
    CHECK(names(rejection(c), "/model/frcition", "is not a recognised field"));
  }
  SECTION("a wrong type") {
    c["impact"]["speed"] = "fast";
    CHECK(names(rejection(c), "/impact/speed", "must be a number"));
  }
  SECTION("a missing required field") {
    c["impact"].erase("speed");
    CHECK(names(rejection(c), "/impact/speed", "is required"));
  }
  SECTION("a missing time limit: one of time_limit (tau) or time_limit_s is required") {
    c["run"].erase("time_limit");
    CHECK(names(rejection(c), "/run", "/run/time_limit: is required"));
    CHECK(names(rejection(c), "/run", "/run/time_limit_s: is required"));
  }
  SECTION("both time limits") {
    c["run"]["time_limit_s"] = 1e-6;
    CHECK(names(rejection(c), "/run", "exactly one"));
  }
  SECTION("a time limit in seconds in a reduced case") {
    c["run"] = {{"time_limit_s", 1e-6}};
    CHECK(names(rejection(c), "/run/time_limit_s", "needs \"units\": \"physical\""));
  }
  SECTION("a bounce share that would let two pieces both hold it") {
    c["classification"] = {{"largest_fragment_share", 0.5}};
    CHECK(names(rejection(c), "/classification/largest_fragment_share", "must be > 0.5"));
  }
  SECTION("a value outside the enumeration") {
    c["model"] = {{"normal", "jkr2"}};
    CHECK(names(rejection(c), "/model/normal", "must be one of \"jkr\", \"dmt\", \"hertz\""));
  }
  SECTION("a non-integer primary count") {
    c["cluster"]["generator"]["primaries"] = 8.5;
    CHECK(names(rejection(c), "/cluster/generator/primaries", "must be an integer"));
  }
  SECTION("both a generator and a file") {
    c["cluster"]["file"] = {{"path", "cluster.xyz"}};
    CHECK(names(rejection(c), "/cluster", "exactly one"));
  }
  SECTION("neither a generator nor a file") {
    c["cluster"] = Json::object();
    CHECK(names(rejection(c), "/cluster", "exactly one"));
  }
  SECTION("rolling resistance without its critical displacement") {
    c["model"] = {{"rolling", {{"enabled", true}}}};
    CHECK(names(rejection(c), "/model/rolling/critical_displacement", "is required"));
  }
  SECTION("rolling resistance without adhesion") {
    c["model"] = {{"normal", "hertz"}, {"rolling", {{"enabled", true}, {"critical_displacement", 0.01}}}};
    CHECK(names(rejection(c), "/model/rolling/enabled", "adhesive normal law"));
  }
  SECTION("an adhesive law without surface energy") {
    c["material"]["gamma_over_kn"] = 0.0;
    CHECK(names(rejection(c), "/material/gamma_over_kn", "must be > 0 for the jkr law"));
  }
  SECTION("an impact angle of 90 degrees") {
    c["impact"]["angle"] = 90;
    CHECK(names(rejection(c), "/impact/angle", "must be < 90"));
  }
  SECTION("a physical field in a reduced case") {
    c["material"]["density"] = 1725.0;
    CHECK(names(rejection(c), "/material/density", "is not a recognised field"));
  }
  SECTION("a physical case without a density") {
    c["units"] = "physical";
    c["material"] = {{"youngs_modulus", 1e10}, {"poisson_ratio", 0.3}, {"surface_energy", 0.05}, {"diameter", 2e-8}};
    CHECK(names(rejection(c), "/material/density", "is required"));
  }
  SECTION("a cluster file that does not exist") {
    c["cluster"] = {{"file", {{"path", "/nonexistent/cluster.xyz"}}}};
    CHECK(names(rejection(c), "/cluster/file/path", "no such file"));
  }
  SECTION("visco-elastic damping without a dissipative time") {
    c["model"] = {{"damping", {{"law", "viscoelastic"}}}};
    CHECK(names(rejection(c), "/model/damping/dissipative_time", "must be > 0"));
  }
  SECTION("several errors are all reported") {
    c["model"] = {{"friction", -1.0}, {"twisting", "yes"}};
    c["impact"]["speed"] = 0;
    const auto v = rejection(c);
    CHECK(names(v, "/model/friction"));
    CHECK(names(v, "/model/twisting", "must be a boolean"));
    CHECK(names(v, "/impact/speed", "must be > 0"));
  }
  SECTION("a schema error does not hide an error of the rules the schema cannot state") {
    c["model"] = {
        {"friction", -1.0}, {"normal", "hertz"}, {"rolling", {{"enabled", true}, {"critical_displacement", 0.01}}}};
    const auto v = rejection(c);
    CHECK(names(v, "/model/friction", "must be >= 0"));
    CHECK(names(v, "/model/rolling/enabled", "adhesive normal law"));
    CHECK(v.size() == 2);
  }
  SECTION("a material in SI without \"units\": the hint, then the case's problems in the units it meant") {
    c["material"] = {{"youngs_modulus", 2.5e10},
                     {"poisson_ratio", 0.3},
                     {"density", 1725.0},
                     {"surface_energy", 0.05},
                     {"diameter", 2e-8}};
    c["run"] = {{"time_limit_s", 3e-7}};
    c["model"] = {{"friction", -1.0}};
    const auto v = rejection(c);
    INFO(describe(v));
    REQUIRE(v.size() == 2);
    CHECK(names(v, "/units", "add \"units\": \"physical\""));
    CHECK(names(v, "/model/friction", "must be >= 0"));
  }
}

TEST_CASE("a file that is not JSON is rejected naming the parse error") {
  const auto path =
      std::filesystem::temp_directory_path() / ("aerobreak_impact_not_json_" + std::to_string(::getpid()) + ".json");
  { std::ofstream(path) << "{\"cluster\": "; }
  CHECK_THROWS_WITH(load_impact_case(path), Contains("is not valid JSON"));
  std::filesystem::remove(path);
}

TEST_CASE("physical units keep gamma/k_n and lambda (eq 19)") {
  // 20 nm ammonium-nitrate-like primaries at 1 m/s (values for the test only).
  Json c = testing::minimal_case();
  c["units"] = "physical";
  c["material"] = {{"youngs_modulus", 2.5e10}, {"poisson_ratio", 0.3}, {"density", 1725.0},
                   {"surface_energy", 0.05},   {"diameter", 2e-8},     {"softening", 0.01}};
  c["impact"]["speed"] = 1.0;
  const ImpactCase p = parse_impact_case(c);
  REQUIRE(p.physical);
  const Material& si = p.physical->material;
  const double kn = si.youngs_modulus * 2e-8 / (3.0 * (1.0 - 0.09));  // eq 7
  CHECK_THAT(p.material.surface_energy, WithinRel(0.05 / kn, 1e-12));
  CHECK_THAT(p.speed, WithinRel(1.0 / p.physical->speed_unit(), 1e-12));
  CHECK_THAT(adhesion_energy_ratio(p.material, 1.0, p.speed), WithinRel(adhesion_energy_ratio(si, 2e-8, 1.0), 1e-9));
  CHECK(p.document["material"]["softening"] == 0.01);
}

TEST_CASE("a physical case may give its time limit in seconds") {
  Json c = testing::minimal_case();
  c["units"] = "physical";
  c["material"] = {{"youngs_modulus", 2.5e10},
                   {"poisson_ratio", 0.3},
                   {"density", 1725.0},
                   {"surface_energy", 0.05},
                   {"diameter", 2e-8}};
  c["impact"]["speed"] = 1.0;
  c["run"] = {{"time_limit_s", 2e-8}};
  const ImpactCase p = parse_impact_case(c);
  REQUIRE(p.physical);
  // tau = sqrt(m/k_n): m = rho pi d^3/6, k_n = E d/(3 (1 - nu^2)) (eq 7).
  const double mass = 1725.0 * std::numbers::pi * 8e-24 / 6.0;
  const double tau = std::sqrt(mass / (2.5e10 * 2e-8 / (3.0 * 0.91)));
  CHECK_THAT(p.time_limit, WithinRel(2e-8 / tau, 1e-12));
  CHECK_FALSE(p.document["run"].contains("time_limit"));
}

TEST_CASE("the schema validator refuses keywords it does not implement") {
  CHECK_THROWS_WITH(JsonSchema(Json::parse(R"({"type": "string", "pattern": "^a"})")), Contains("\"pattern\""));
  CHECK_THROWS_WITH(JsonSchema(Json::parse(R"({"$ref": "#/$defs/missing"})")), Contains("unresolved"));
  CHECK_NOTHROW(case_schema());
  CHECK_NOTHROW(result_schema());
}
