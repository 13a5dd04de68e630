// A case's physical inputs as every reader reads them (engine/impact/case_inputs.hpp): the engine's
// case, the store's N and the lookup tables' grid-point inputs come from the completed document.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "engine/impact/case_inputs.hpp"
#include "engine/impact/impact_case.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;
using Catch::Matchers::WithinRel;

TEST_CASE("a reduced case's inputs: gamma/k_n, nu, speed, angle, the generator's N and D_f") {
  Json c = testing::minimal_case();
  c["material"]["poisson_ratio"] = 0.25;
  c["impact"]["angle"] = 30.0;
  c["cluster"]["generator"] = {
      {"method", "tunable"}, {"primaries", 64}, {"seed", 3}, {"fractal_dimension", 1.8}, {"prefactor", 1.3}};
  const ImpactCase parsed = parse_impact_case(c);
  const CaseInputs inputs = read_case_inputs(parsed.document);
  CHECK_FALSE(inputs.physical);
  CHECK(inputs.material.surface_energy == 0.01);
  CHECK(inputs.material.poisson_ratio == 0.25);
  CHECK_THAT(inputs.material.youngs_modulus, WithinRel(3.0 * (1.0 - 0.25 * 0.25), 1e-15));  // eq 7, k_n = d = 1
  CHECK(inputs.speed == 0.01);
  CHECK(inputs.angle_degrees == 30.0);
  CHECK(inputs.primaries == 64);
  CHECK(inputs.fractal_dimension == 1.8);
  // The engine's case is read by the same function.
  CHECK(parsed.speed == inputs.speed);
  CHECK(parsed.angle_degrees == inputs.angle_degrees);
  CHECK(parsed.material.youngs_modulus == inputs.material.youngs_modulus);
}

TEST_CASE("a physical case's inputs are reduced by its own material (eq 7), softening kept") {
  Json c = testing::minimal_case();
  c["units"] = "physical";
  c["material"] = {{"youngs_modulus", 2.5e10}, {"poisson_ratio", 0.3}, {"density", 1725.0},
                   {"surface_energy", 0.05},   {"diameter", 2e-8},     {"softening", 0.01}};
  c["impact"]["speed"] = 2.0;
  const CaseInputs inputs = read_case_inputs(parse_impact_case(c).document);
  REQUIRE(inputs.physical);
  CHECK(inputs.physical->softening == 0.01);
  CHECK(inputs.physical->diameter == 2e-8);
  const double kn = 2.5e10 * 2e-8 / (3.0 * (1.0 - 0.09));  // eq 7
  const double mass = 1725.0 * std::numbers::pi * 8e-24 / 6.0;
  CHECK_THAT(inputs.material.surface_energy, WithinRel(0.05 / kn, 1e-12));
  CHECK_THAT(inputs.speed, WithinRel(2.0 / (2e-8 / std::sqrt(mass / kn)), 1e-12));  // v tau / d
  CHECK(inputs.primaries == 8);
  CHECK_FALSE(inputs.fractal_dimension);  // ballistic: no target
}

TEST_CASE("a case's inputs without N: a cluster file, a damaged document") {
  Json file_case = testing::minimal_case();
  file_case["cluster"] = {{"file", {{"path", "cluster.xyz"}}}};
  CHECK_FALSE(read_case_inputs(file_case).primaries);

  const CaseInputs nothing = read_case_inputs(Json::parse(R"({"cluster": {"generator": {"primaries": "many"}}})"));
  CHECK_FALSE(nothing.primaries);
  CHECK(std::isnan(nothing.speed));
  CHECK(std::isnan(nothing.material.surface_energy));
  CHECK(nothing.angle_degrees == 0.0);
  CHECK_FALSE(read_case_inputs(Json()).primaries);  // not even an object

  // A whole number written as a double (a study's range) is N; a fraction is not.
  CHECK(read_case_inputs(Json::parse(R"({"cluster": {"generator": {"primaries": 32.0}}})")).primaries == 32);
  CHECK_FALSE(read_case_inputs(Json::parse(R"({"cluster": {"generator": {"primaries": 32.5}}})")).primaries);
}
