// `cmake --install` as a site installs aerobreak: into a temporary prefix, which is then moved as a
// whole, and run from another directory, the installed binary runs a case, a study on workers that
// are itself, and serves its dashboard from the prefix, not from the source tree it was built from.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/orchestrator/service_process.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {
namespace {

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A command run in `directory`.
CommandOutput run_in(const std::filesystem::path& directory, const std::string& command) {
  return run_command("cd '" + directory.string() + "' && " + command);
}

}  // namespace

TEST_CASE("An installed prefix, moved, runs a case, a study and serves its dashboard from itself", "[install]") {
  ScratchDirectory scratch("install");
  const auto installed = scratch.path() / "installed";
  const auto install = run_command(std::string("'") + CMAKE_COMMAND + "' --install '" + AEROBREAK_BUILD_DIR +
                                   "' --prefix '" + installed.string() + "'");
  INFO(install.text);
  REQUIRE(install.exit_code == 0);
  const auto prefix = scratch.path() / "moved";
  std::filesystem::rename(installed, prefix);  // a prefix moved as a whole still works
  const auto elsewhere = scratch.path() / "elsewhere";
  std::filesystem::create_directories(elsewhere);
  const std::string aerobreak = (prefix / "bin" / "aerobreak").string();
  const auto share = prefix / "share" / "aerobreak";

  for (const auto* file : {"web/index.html", "web/vendor.json", "schemas/case.schema.json", "schemas/study.schema.json",
                           "schemas/openapi.json", "studies/default.study.json", "studies/examples/stick.case.json"})
    CHECK(std::filesystem::is_regular_file(share / file));
  CHECK(std::filesystem::is_regular_file(prefix / "share" / "doc" / "aerobreak" / "README.md"));
  // The dashboard's default folder is the moved prefix's.
  const auto help = run_in(elsewhere, "'" + aerobreak + "' serve --help");
  CHECK_THAT(help.text, Catch::Contains((share / "web").string()));

  SECTION("a case, validated and run") {
    const auto example = share / "studies" / "examples" / "stick.case.json";
    const auto result = run_in(elsewhere, "'" + aerobreak + "' impact '" + example.string() + "' -o stick.result.json");
    INFO(result.text);
    CHECK(result.exit_code == 0);
    CHECK(Json::parse(file_text(elsewhere / "stick.result.json"))["outcome"]["class"] == "stick");
    auto bad = Json::parse(file_text(example));
    bad["cluster"]["generator"]["primaries"] = 0;
    std::ofstream(elsewhere / "bad.case.json") << bad.dump();
    const auto refused = run_in(elsewhere, "'" + aerobreak + "' impact bad.case.json -o bad.result.json");
    CHECK(refused.exit_code != 0);
    CHECK_THAT(refused.text, Catch::Contains("/cluster/generator/primaries"));
  }

  SECTION("a study on workers that are the installed binary") {
    std::ofstream(elsewhere / "tiny.study.json") << small_study("installed", {0.005, 0.05}, 2, 8).dump();
    const auto run =
        run_in(elsewhere, "'" + aerobreak + "' run tiny.study.json --store tiny.sqlite --ranks 1 --port 0");
    INFO(run.text);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.text, Catch::Contains("4 done, 0 failed"));
  }

  SECTION("the dashboard, served from the prefix") {
    std::ofstream(share / "web" / "index.html", std::ios::app) << "<!-- the installed copy -->\n";
    ServiceProcess service(elsewhere, {"--ranks", "1"}, {}, aerobreak);
    auto client = service.client();
    const auto page = client.Get("/");
    REQUIRE(page);
    CHECK(page->status == 200);
    CHECK_THAT(page->body, Catch::Contains("the installed copy"));
    for (const auto* path : {"/app.css", "/src/main.js", "/vendor/uPlot.esm.js"}) {
      const auto asset = client.Get(path);
      REQUIRE(asset);
      INFO(path);
      CHECK(asset->status == 200);
      CHECK_FALSE(asset->body.empty());
    }
    CHECK(service.kill(SIGTERM) == 0);
  }
}

}  // namespace aerobreak::testing
