// Every file the command line reads is bounded as the service bounds a request (regular files
// only, 1 MiB for a JSON document, 64 levels of nesting, numbers a double holds), and a bad one
// gets an exit status and a message naming the file and the problem, never an abort, a segfault
// or a wait for good. Each command runs as the real program under `timeout`, so that a hang
// fails the test instead of holding it.
#include <catch2/catch.hpp>

#include <sqlite3.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch_directory.hpp"

namespace {

using aerobreak::testing::CommandOutput;
using aerobreak::testing::ScratchDirectory;

// `timeout` exits 124 for a command that ran past 20 s; a signal shows as 128 + its number.
CommandOutput run_aerobreak(const std::string& arguments) {
  return aerobreak::testing::run_command("timeout 20 " + std::string(AEROBREAK_BINARY) + " " + arguments);
}

std::string nested_arrays(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

std::string small_case(const std::string& cluster) {
  return R"({"cluster": )" + cluster +
         R"(, "material": {"gamma_over_kn": 0.001}, "impact": {"speed": 0.01}, "run": {"time_limit": 100}})";
}

// A case naming 16 primaries that all sit at one point.
std::string one_point_cluster() {
  std::string text;
  for (int i = 0; i < 16; ++i) text += "0 0 0 0.5\n";
  return text;
}

}  // namespace

TEST_CASE("100,000 nested arrays are refused by impact --check and study expand, naming the file", "[cli][hostile]") {
  const ScratchDirectory dir("nested_input");
  const auto file = dir.write("nested.json", nested_arrays(100000));
  const CommandOutput impact = run_aerobreak("impact --check " + file.string());
  INFO(impact.text);
  CHECK(impact.exit_code == 2);  // an invalid case (README, "Exit status")
  CHECK_THAT(impact.text, Catch::Contains(file.string()) && Catch::Contains("nest deeper than 64 levels"));

  const CommandOutput expand = run_aerobreak("study expand " + file.string());
  INFO(expand.text);
  CHECK(expand.exit_code == 2);
  CHECK_THAT(expand.text, Catch::Contains(file.string()) && Catch::Contains("nest deeper than 64 levels"));
}

TEST_CASE("a number no double holds (1e999) in a case is refused, not an abort", "[cli][hostile]") {
  const ScratchDirectory dir("huge_number");
  const auto file = dir.write("huge.case.json", R"({"cluster": {"generator": {"primaries": 8, "seed": 1}},
      "material": {"gamma_over_kn": 1e999}, "impact": {"speed": 0.01}, "run": {"time_limit": 100}})");
  const CommandOutput impact = run_aerobreak("impact --check " + file.string());
  INFO(impact.text);
  CHECK(impact.exit_code == 2);  // an invalid case (README, "Exit status")
  CHECK_THAT(impact.text, Catch::Contains(file.string()) && Catch::Contains("beyond what a double holds"));
}

TEST_CASE("a document over 1 MiB is refused before it is read", "[cli][hostile]") {
  const ScratchDirectory dir("large_input");
  const auto file = dir.write("large.study.json", "{\"name\": \"" + std::string(1100000, 'x') + "\"}");
  const CommandOutput expand = run_aerobreak("study expand " + file.string());
  INFO(expand.text.substr(0, 2000));
  CHECK(expand.exit_code == 2);
  CHECK_THAT(expand.text, Catch::Contains(file.string()) && Catch::Contains("bytes, more than the 1048576 read here"));
}

TEST_CASE("a cluster file's bad line is quoted in part, however long it is", "[cli][hostile]") {
  const ScratchDirectory dir("long_line");
  const auto file = dir.write("one_line.xyz", std::string(1000000, '['));
  const CommandOutput analyse = run_aerobreak("cluster analyse " + file.string());
  INFO(analyse.text.substr(0, 2000));
  CHECK(analyse.exit_code == 1);
  CHECK_THAT(analyse.text, Catch::Contains(file.string() + ":1: expected") && Catch::Contains("[[[...'"));
  CHECK(analyse.text.size() < 1000);
}

TEST_CASE("a FIFO or a device named as an input is refused at once, not waited on", "[cli][hostile]") {
  const ScratchDirectory dir("special_input");
  const std::string fifo = dir.file("case.json");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const CommandOutput impact = run_aerobreak("impact --check " + fifo);
  INFO(impact.text);
  CHECK(impact.exit_code == 2);  // an invalid case (README, "Exit status")
  CHECK_THAT(impact.text, Catch::Contains(fifo) && Catch::Contains("is a FIFO (named pipe), not a regular file"));

  const CommandOutput expand = run_aerobreak("study expand " + fifo);
  CHECK(expand.exit_code == 2);
  CHECK_THAT(expand.text, Catch::Contains("is a FIFO (named pipe), not a regular file"));

  const CommandOutput analyse = run_aerobreak("cluster analyse /dev/zero");
  INFO(analyse.text);
  CHECK(analyse.exit_code != 0);
  CHECK(analyse.exit_code != 124);
  CHECK_THAT(analyse.text, Catch::Contains("/dev/zero") && Catch::Contains("is a device, not a regular file"));

  const auto fifo_cluster = dir.write("fifo_cluster.case.json", small_case(R"({"file": {"path": "cluster.xyz"}})"));
  REQUIRE(::mkfifo(dir.file("cluster.xyz").c_str(), 0600) == 0);
  const CommandOutput cluster = run_aerobreak("impact --check " + fifo_cluster.string());
  INFO(cluster.text);
  CHECK(cluster.exit_code == 2);
  CHECK_THAT(cluster.text, Catch::Contains("cluster.xyz"));
}

TEST_CASE("a truncated cluster library is an invalid case naming the file, not an uncaught exception",
          "[cli][hostile]") {
  const ScratchDirectory dir("truncated_library");
  const std::string library = dir.file("clusters.h5");
  const CommandOutput generated = run_aerobreak("cluster generate --primaries 16 --count 2 --output " + library);
  REQUIRE(generated.exit_code == 0);
  std::filesystem::resize_file(library, 4000);
  const auto case_file = dir.write("truncated.case.json",
                                   small_case(R"({"file": {"path": "clusters.h5", "name": "ballistic-N16-seed1-0"}})"));
  for (const std::string options : {"--check ", "-q "}) {
    const CommandOutput impact = run_aerobreak("impact " + options + case_file.string());
    INFO(impact.text);
    CHECK(impact.exit_code == 2);  // an invalid case (README, "Exit status")
    CHECK_THAT(impact.text,
               Catch::Contains("/cluster/file/path") && Catch::Contains(library) && Catch::Contains("truncated file"));
  }
}

TEST_CASE("16 primaries at one point are refused at input, naming the pair", "[cli][hostile]") {
  const ScratchDirectory dir("one_point");
  dir.write("cluster.xyz", one_point_cluster());
  const auto case_file = dir.write("one_point.case.json", small_case(R"({"file": {"path": "cluster.xyz"}})"));
  for (const std::string options : {"--check ", "-q "}) {
    const CommandOutput impact = run_aerobreak("impact " + options + case_file.string());
    INFO(impact.text);
    CHECK(impact.exit_code == 2);  // an invalid case (README, "Exit status")
    CHECK_THAT(impact.text, Catch::Contains("primaries 0 and ") && Catch::Contains("overlap by 1 d") &&
                                Catch::Contains("small-strain range"));
  }

  // Overlaps within the range (a tenth of the radius) are accepted.
  dir.write("cluster.xyz", "0 0 0 0.5\n0 0 0.95 0.5\n");
  const CommandOutput accepted = run_aerobreak("impact --check " + case_file.string());
  INFO(accepted.text);
  CHECK(accepted.exit_code == 0);
}

namespace {

// An SQLite database made by `sql`, as another program (or a newer aerobreak) would leave it.
void make_database(const std::string& file, const std::string& sql) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(file.c_str(), &db) == SQLITE_OK);
  REQUIRE(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(db);
}

std::string bytes_of(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("serve and export refuse a file that is not their store, and leave it unchanged", "[cli][hostile]") {
  const ScratchDirectory dir("foreign_store");
  const std::string foreign = dir.file("addresses.sqlite");
  make_database(foreign, "CREATE TABLE addresses (name TEXT, street TEXT); INSERT INTO addresses VALUES ('a', 'b');");
  const std::string before = bytes_of(foreign);
  const CommandOutput serve = run_aerobreak("serve --port 0 --store " + foreign);
  INFO(serve.text);
  CHECK(serve.exit_code == 1);
  CHECK_THAT(serve.text, Catch::Contains("is an SQLite database of another program, not an aerobreak store"));
  CHECK(bytes_of(foreign) == before);
  CHECK_FALSE(std::filesystem::exists(foreign + "-wal"));

  // A store of a newer aerobreak: no advice to upgrade it with this one.
  const std::string newer = dir.file("newer.sqlite");
  std::string tables;
  for (const char* table : {"studies", "jobs", "cases", "study_cases", "attempts", "results", "fragments"})
    tables += "CREATE TABLE " + std::string(table) + " (id INTEGER);";
  make_database(newer, tables + "PRAGMA user_version = 999;");
  const CommandOutput export_newer = run_aerobreak("export --store " + newer + " --study 1");
  INFO(export_newer.text);
  CHECK(export_newer.exit_code == 1);
  CHECK_THAT(export_newer.text, Catch::Contains("a store of a newer aerobreak (schema version 999"));
  CHECK_THAT(export_newer.text, !Catch::Contains("upgrade"));

  const CommandOutput negative = run_aerobreak("export --store " + newer + " --study -1");
  INFO(negative.text);
  CHECK(negative.exit_code != 0);
  CHECK_THAT(negative.text, Catch::Contains("--study") && Catch::Contains("not in range 1 to"));
}
