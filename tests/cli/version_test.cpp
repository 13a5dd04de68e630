#include <catch2/catch.hpp>

#include <regex>
#include <string>

#include "engine/core/version.hpp"
#include "tests/support/run_command.hpp"

using aerobreak::testing::run_command;

TEST_CASE("aerobreak --version prints the project version and a git commit") {
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " --version");
  CHECK(out.exit_code == 0);
  const std::regex pattern(R"(aerobreak (\d+\.\d+\.\d+) \(commit ([0-9a-f]{12}(-dirty)?|unknown)\)\s*)");
  std::smatch match;
  REQUIRE(std::regex_match(out.text, match, pattern));
  CHECK(match[1] == std::string(aerobreak::version()));
}

TEST_CASE("aerobreak --help lists every subcommand") {
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " --help");
  CHECK(out.exit_code == 0);
  for (const char* sub : {"run", "serve", "study", "impact", "cluster", "bench"}) {
    INFO(sub);
    CHECK(out.text.find(std::string("  ") + sub) != std::string::npos);
  }
}

TEST_CASE("an unknown subcommand is an error, not silence") {
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " no-such-command");
  CHECK(out.exit_code != 0);
  CHECK(out.text.find("no-such-command") != std::string::npos);
}
