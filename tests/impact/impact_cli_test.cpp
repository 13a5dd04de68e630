// `aerobreak impact`: a case file in, a valid result document out; invalid cases are refused
// with the offending field named on stderr and exit status 2 (README, "Exit status").
#include <catch2/catch.hpp>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch_directory.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <unistd.h>

#include "engine/core/units.hpp"
#include "engine/impact/impact_result.hpp"
#include "engine/impact/impact_run.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;
using Catch::Matchers::Contains;

namespace {

using aerobreak::testing::run_command;

}  // namespace

TEST_CASE("aerobreak impact runs a case and writes a valid result document and trajectories") {
  const aerobreak::testing::ScratchDirectory scratch("impact_cli");
  Json c = testing::minimal_case();
  c["run"]["time_limit"] = 400.0;
  c["run"]["snapshot_interval"] = 100.0;
  const std::string case_file = scratch.write("case.json", c.dump(2)).string();
  const std::string result_file = (scratch.path() / "result.json").string();
  const std::string trajectory = (scratch.path() / "trajectory.h5").string();
  const std::string xyz = (scratch.path() / "trajectory.xyz").string();
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " impact " + case_file + " -o " + result_file +
                               " --trajectory " + trajectory + " --xyz " + xyz + " --progress-seconds 0.001");
  INFO(out.text);
  REQUIRE(out.exit_code == 0);
  CHECK_THAT(out.text, Contains("impact: t = "));  // progress on stderr
  std::ifstream in(result_file);
  const Json result = Json::parse(in);
  const auto violations = validate_result(result);
  INFO(describe(violations));
  CHECK(violations.empty());
  CHECK(result["case"]["run"]["time_limit"] == 400.0);
  CHECK(result["run"]["snapshots"].get<int>() >= 5);
  // The stepping's CPU time (one thread: never more than its wall-clock time) and the rate by it.
  const double cpu = result["run"]["cpu_seconds"].get<double>();
  CHECK(cpu > 0.0);
  CHECK(cpu <= result["run"]["wall_clock_seconds"].get<double>() * 1.01 + 1e-3);
  CHECK(result["run"]["particle_steps_per_cpu_second"].get<double>() > 0.0);
  CHECK(std::filesystem::file_size(trajectory) > 0);
  std::ifstream frames(xyz);
  std::string first;
  std::getline(frames, first);
  CHECK(first == "8");
}

TEST_CASE("aerobreak impact refuses an invalid case and names the field") {
  const aerobreak::testing::ScratchDirectory scratch("impact_cli");
  Json c = testing::minimal_case();
  c["model"] = {{"friction", -0.5}};
  const auto out =
      run_command(std::string(AEROBREAK_BINARY) + " impact " + scratch.write("bad.json", c.dump(2)).string());
  CHECK(out.exit_code == 2);
  CHECK_THAT(out.text, Contains("/model/friction: must be >= 0 (got -0.5)"));
}

TEST_CASE("aerobreak impact --check says a case without rolling resistance has none, instead of E_roll = nan") {
  const aerobreak::testing::ScratchDirectory scratch("impact_cli");
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " impact -o /dev/null --check " + AEROBREAK_SOURCE_DIR +
                               "/studies/figure4_impact_n256.case.json");
  INFO(out.text);
  REQUIRE(out.exit_code == 0);
  CHECK_THAT(out.text, Contains("impact: E_roll: no rolling resistance (/model/rolling/enabled is false)"));
  CHECK_THAT(out.text, !Contains("nan"));
}

TEST_CASE("aerobreak impact --check writes the case completed with its defaults") {
  const aerobreak::testing::ScratchDirectory scratch("impact_cli");
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " impact --check " +
                                   scratch.write("case.json", testing::minimal_case().dump(2)).string(),
                               true);
  REQUIRE(out.exit_code == 0);
  const Json completed = Json::parse(out.text);
  CHECK(completed["model"]["normal"] == "jkr");
  CHECK(completed["impact"]["gap"] == 0.01);
}

TEST_CASE("aerobreak impact --check prints tau, the time step, lambda and the energy groups") {
  const aerobreak::testing::ScratchDirectory scratch("impact_cli");
  Json c = testing::minimal_case();
  c["units"] = "physical";
  c["material"] = {{"youngs_modulus", 2.5e10},
                   {"poisson_ratio", 0.3},
                   {"density", 1725.0},
                   {"surface_energy", 0.05},
                   {"diameter", 2e-8}};
  c["impact"]["speed"] = 1.0;
  c["model"] = {{"rolling", {{"enabled", true}, {"critical_displacement", 0.02}}}};
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " impact -o /dev/null --check " +
                               scratch.write("case.json", c.dump(2)).string());
  INFO(out.text);
  REQUIRE(out.exit_code == 0);
  // The case's own numbers, from the engine's functions.
  const ImpactCase parsed = parse_impact_case(c);
  const ImpactResult prepared = prepare_impact(parsed).result;
  const auto line = [](const char* format, double x) {
    char text[160];
    std::snprintf(text, sizeof text, format, x);
    return std::string(text);
  };
  CHECK_THAT(out.text, Contains(line("time unit tau = sqrt(m/k_n) = %.4g s", parsed.physical->time_unit())));
  CHECK_THAT(out.text, Contains(line("time step %.6g tau", prepared.time_step)));
  CHECK_THAT(out.text,
             Contains(line("lambda (eq 19) = %.6g", adhesion_energy_ratio(parsed.material, 1.0, parsed.speed))));
  CHECK_THAT(out.text, Contains(line("E_kin / (N_c E_break) = %.6g", prepared.energy_groups.energy_per_contact)));
  CHECK_THAT(out.text, Contains(line("E_kin / E_roll = %.6g", prepared.energy_groups.energy_over_rolling)));
  CHECK_THAT(out.text, Contains("(1.5426 F_c delta_c)"));
  CHECK_THAT(out.text, !Contains("impact: t = "));  // nothing ran
}
