// `aerobreak study expand` over the real binary, and the project's default study.
#include <catch2/catch.hpp>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <set>
#include <string>

#include "study_support.hpp"
#include "tests/support/run_command.hpp"

using namespace aerobreak;
using aerobreak::testing::minimal_study;
using aerobreak::testing::run_command;
using aerobreak::testing::ScratchDirectory;
using aerobreak::testing::source_path;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using Json = nlohmann::ordered_json;

namespace {

const std::string kExpand = std::string(AEROBREAK_BINARY) + " study expand ";

// A loopback port nothing listens on: one the kernel just handed out, closed again.
int closed_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  REQUIRE(fd >= 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
  socklen_t length = sizeof address;
  REQUIRE(::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0);
  ::close(fd);
  return ntohs(address.sin_port);
}

}  // namespace

TEST_CASE("the default study parses, as a file and as a service would take it") {
  const Study study = load_study(source_path("studies/default.study.json"));
  CHECK(study.name == "default");
  CHECK_FALSE(study.description.empty());
  REQUIRE(study.axes.size() == 3);
  CHECK(study.axes[0].name == "impact_speed");
  CHECK(study.axes[1].name == "/wall/adhesive");
  CHECK(study.axes[1].values.size() == 2);
  CHECK(study.axes[2].name == "primaries");
  CHECK(study.axes[2].values.size() == 2);
  CHECK(study.replicates > 1);

  const auto cases = study.cases;
  CHECK(cases.size() == study.case_count());
  std::set<std::string> hashes;
  std::set<bool> walls;
  for (const auto& c : cases) {
    hashes.insert(c.hash);
    walls.insert(c.document["wall"]["adhesive"].get<bool>());
    CHECK(c.document["units"] == "physical");
    CHECK(c.document["model"]["damping"]["law"] == "viscoelastic");
  }
  CHECK(hashes.size() == cases.size());
  CHECK(walls == std::set<bool>{false, true});  // both walls: stick needs one, bounce the other

  // Over HTTP: no cluster files, tighter limits.
  StudyLimits service;
  service.max_cases = 1000;
  service.max_primaries = 4096;
  service.allow_cluster_files = false;
  std::ifstream in(source_path("studies/default.study.json"));
  CHECK(parse_study(Json::parse(in), service).hash == study.hash);
}

TEST_CASE("aerobreak study expand lists the cases: count, then index, hash, grid point and replicate") {
  ScratchDirectory scratch("cli_table");
  Json s = minimal_study();
  s["replicates"] = {{"count", 2}};
  const auto out = run_command(kExpand + scratch.write("study.json", s.dump()).string(), true);
  INFO(out.text);
  REQUIRE(out.exit_code == 0);
  const Study study = parse_study(s);
  const auto cases = study.cases;
  CHECK_THAT(out.text, StartsWith("test study: 4 cases (study " + study.hash.substr(0, 12) + ")\n"));
  CHECK_THAT(out.text, Contains("     0  " + cases[0].hash.substr(0, 12) +
                                "  {\"impact_speed\":0.01,\"gamma_over_kn\":0.001,\"primaries\":8}  replicate 0\n"));
  CHECK_THAT(out.text, Contains("     3  " + cases[3].hash.substr(0, 12) +
                                "  {\"impact_speed\":0.02,\"gamma_over_kn\":0.001,\"primaries\":8}  replicate 1\n"));
}

TEST_CASE("aerobreak study expand --json prints the cases with their complete documents") {
  const std::string study_file = source_path("studies/default.study.json").string();
  const auto out = run_command(kExpand + study_file + " --json", true);
  REQUIRE(out.exit_code == 0);
  const Json printed = Json::parse(out.text);
  const auto cases = load_study(study_file).cases;
  REQUIRE(printed.size() == cases.size());
  for (std::size_t k = 0; k < cases.size(); k += 37) {
    INFO("case " << k);
    CHECK(printed[k]["hash"] == cases[k].hash);
    CHECK(printed[k]["grid_point"] == cases[k].grid_point);
    CHECK(printed[k]["replicate"] == cases[k].replicate);
    CHECK(printed[k]["document"] == cases[k].document);
    CHECK(case_hash(printed[k]["document"]) == cases[k].hash);
  }
}

TEST_CASE("aerobreak study expand refuses a bad study with each violation on stderr and status 2") {
  ScratchDirectory scratch("cli_bad");
  Json s = minimal_study();
  s["axes"]["speed"] = {{"values", {1}}};
  s["replicates"] = {{"count", 0}};
  auto out = run_command(kExpand + scratch.write("bad.json", s.dump()).string());
  CHECK(out.exit_code == 2);
  CHECK_THAT(out.text, Contains("invalid study"));
  CHECK_THAT(out.text, Contains("  /replicates/count: must be >= 1 (got 0)\n"));
  CHECK_THAT(out.text, Contains("  /axes/speed: is neither an axis alias"));
  CHECK(run_command(kExpand + scratch.write("bad.json", s.dump()).string(), true).text.empty());

  out = run_command(kExpand + scratch.write("broken.json", "{").string());
  CHECK(out.exit_code == 2);
  CHECK_THAT(out.text, Contains("is not valid JSON"));

  out = run_command(kExpand + (scratch.path() / "absent.json").string());
  CHECK(out.exit_code == 2);
  CHECK_THAT(out.text, Contains("cannot open study file"));
}

TEST_CASE("aerobreak study needs a subcommand") {
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " study");
  CHECK(out.exit_code != 0);
  CHECK_THAT(out.text, Contains("A subcommand is required"));
  const auto help = run_command(std::string(AEROBREAK_BINARY) + " study --help");
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.text, Contains("expand"));
}

TEST_CASE("aerobreak study without a service says so in whole sentences, with status 4") {
  const std::string url = "http://127.0.0.1:" + std::to_string(closed_port());
  const auto out = run_command(std::string(AEROBREAK_BINARY) + " study list --url " + url);
  INFO(out.text);
  CHECK(out.exit_code == 4);
  CHECK_THAT(out.text, Contains("aerobreak study list: no answer from the service at " + url +
                                ": nothing accepts connections there."));
  CHECK_THAT(out.text, Contains("aerobreak serve") && Contains("--url or AEROBREAK_URL."));
}

TEST_CASE("a command line aerobreak does not understand ends with status 2, not CLI11's own") {
  CHECK(run_command(std::string(AEROBREAK_BINARY) + " study expand").exit_code == 2);                 // missing file
  CHECK(run_command(std::string(AEROBREAK_BINARY) + " run --no-such-option x.json").exit_code == 2);  // unknown option
  CHECK(run_command(std::string(AEROBREAK_BINARY) + " impact /no/such/case.json").exit_code == 2);    // file not there
  CHECK(run_command(std::string(AEROBREAK_BINARY) + " --help").exit_code == 0);
}
