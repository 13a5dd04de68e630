// `aerobreak bench` prints its figures: one row per size, particle-steps per second, and the share
// of steps run in wavefronts, which follows --wavefront-from.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

using aerobreak::testing::run_command;

namespace {

// The table row of size n, split into its columns.
std::vector<std::string> row_of(const std::string& text, const std::string& n) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::vector<std::string> columns;
    for (std::string word; words >> word;) columns.push_back(word);
    if (!columns.empty() && columns.front() == n) return columns;
  }
  return {};
}

}  // namespace

TEST_CASE("aerobreak bench prints particle-steps per second and the share of steps in wavefronts") {
  const auto out = run_command(std::string(AEROBREAK_BINARY) +
                               " bench --sizes 64,128 --steps 40 --wavefront-from 100 --wavefront-depth 8");
  REQUIRE(out.exit_code == 0);
  const std::vector<std::string> small = row_of(out.text, "64"), large = row_of(out.text, "128");
  // N, contacts, steps, dt, seconds, particle-steps/s, ns/p-step, pairs/N, rebuilds, wavefront,
  // CPU seconds, particle-steps per CPU second
  REQUIRE(small.size() == 12);
  REQUIRE(large.size() == 12);
  CHECK(std::stod(small[5]) > 0.0);
  CHECK(std::stod(large[5]) > 0.0);
  // the CPU time of the stepping is never more than its wall-clock time (one thread)
  CHECK(std::stod(small[10]) <= std::stod(small[4]) * 1.01 + 0.002);
  CHECK(std::stod(large[11]) > 0.0);
  CHECK(small[9] == "0%");  // below --wavefront-from: one step at a time
  CHECK(large[9] != "0%");  // from it on: in wavefronts
  CHECK(std::stoi(large[2]) == 40);
}

TEST_CASE("aerobreak bench's header names the model the options set") {
  const auto full = run_command(std::string(AEROBREAK_BINARY) + " bench --sizes 64 --steps 2");
  REQUIRE(full.exit_code == 0);
  CHECK_THAT(full.text, Catch::Contains("JKR (displacement rule) + visco-elastic damping (A = 0.05 tau) + Mindlin "
                                        "(mu = 0.5) + rolling + twisting; adhesive wall"));
  const auto bare = run_command(std::string(AEROBREAK_BINARY) +
                                " bench --sizes 64 --steps 2 --damping 0 --no-rolling --no-twisting --separation force"
                                " --no-wall-adhesion");
  REQUIRE(bare.exit_code == 0);
  CHECK_THAT(bare.text,
             Catch::Contains("JKR (force rule) + no damping + Mindlin (mu = 0.5) + no rolling + no twisting; "
                             "non-adhesive wall"));
}

TEST_CASE("aerobreak bench refuses a wavefront depth below 1") {
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " bench --sizes 64 --wavefront-depth 0");
  CHECK(out.exit_code != 0);
  CHECK(out.text.find("wavefront-depth") != std::string::npos);
}
