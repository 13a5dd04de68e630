// A small study through the real service: submitted with `aerobreak study submit` over loopback
// HTTP, run by `mpirun -np 2` worker jobs, committed into a real SQLite file, read back through
// the REST API and from the file itself.
#include <sqlite3.h>

#include <map>
#include <set>

#include "tests/orchestrator/service_process.hpp"
#include "tests/support/run_command.hpp"

namespace aerobreak::testing {
namespace {

long long count_rows(const std::filesystem::path& file, const std::string& sql) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
  sqlite3_stmt* statement = nullptr;
  REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr) == SQLITE_OK);
  REQUIRE(sqlite3_step(statement) == SQLITE_ROW);
  const long long value = sqlite3_column_int64(statement, 0);
  sqlite3_finalize(statement);
  sqlite3_close(db);
  return value;
}

}  // namespace

TEST_CASE("A study runs end to end: CLI client, REST API, mpirun -np 2 workers, SQLite store", "[service]") {
  ScratchDirectory scratch("end-to-end");
  ServiceProcess service(scratch.path());
  const auto study_file = scratch.path() / "study.json";
  std::ofstream(study_file) << small_study("end to end", {0.005, 0.02, 0.08}, 2).dump(2);

  const auto submitted = run_command(
      std::string(AEROBREAK_BINARY) + " study submit --json --url " + service.url() + " " + study_file.string(), true);
  INFO(submitted.text);
  REQUIRE(submitted.exit_code == 0);
  const auto receipt = Json::parse(submitted.text);
  CHECK(receipt.at("cases") == 6);
  CHECK(receipt.at("new_cases") == 6);
  const auto study = receipt.at("id").get<std::int64_t>();

  REQUIRE(eventually([&] { return study_complete(service, study); }, 120s));
  const auto progress = service.get("/api/studies/" + std::to_string(study) + "/progress");
  CHECK(progress.at("counts").at("done") == 6);
  CHECK(progress.at("cases_per_hour").get<double>() > 0.0);

  const auto results = service.get("/api/studies/" + std::to_string(study) + "/results?limit=4");
  CHECK(results.at("total") == 6);
  CHECK(results.at("items").size() == 4);
  std::set<std::string> outcomes{"stick", "bounce", "break-up", "undetermined"};
  for (const auto& result : results.at("items")) {
    CHECK(outcomes.count(result.at("outcome").get<std::string>()) == 1);
    REQUIRE(result.at("data_file").is_string());
    CHECK(std::filesystem::exists(result.at("data_file").get<std::string>()));
  }

  // Both ranks of the job got work: cases are handed out one at a time to whichever rank is free.
  std::set<std::string> workers;
  const auto cases = service.get("/api/studies/" + std::to_string(study) + "/cases");
  for (const auto& record : cases.at("items")) workers.insert(record.at("worker").get<std::string>());
  CHECK(workers.size() == 2);

  // The outcome table counts, per grid point, the results flagged outside the small-strain range
  // and averages their retained mass fraction, as the results themselves say.
  std::map<std::string, std::pair<long long, double>> flagged_and_retained;
  const auto all_results = service.get("/api/studies/" + std::to_string(study) + "/results");
  for (const auto& result : all_results.at("items")) {
    REQUIRE(result.at("small_strain_exceeded").is_boolean());
    REQUIRE(result.at("retained_mass_fraction").is_number());
    auto& [flagged, retained] = flagged_and_retained[result.at("grid_point").dump()];
    flagged += result.at("small_strain_exceeded").get<bool>() ? 1 : 0;
    retained += result.at("retained_mass_fraction").get<double>() / 2.0;
  }
  const auto table = service.get("/api/studies/" + std::to_string(study) + "/outcomes");
  REQUIRE(table.at("grid_points").size() == 3);
  for (const auto& point : table.at("grid_points")) {
    CHECK(point.at("finished") == 2);
    long long total = 0;
    for (const auto& [outcome, estimate] : point.at("outcomes").items()) total += estimate.at("count").get<long long>();
    CHECK(total == 2);
    const auto& [flagged, retained] = flagged_and_retained.at(point.at("grid_point").dump());
    CHECK(point.at("small_strain_exceeded") == flagged);
    CHECK(point.at("small_strain_unchecked") == 0);
    CHECK(point.at("retained_mass_fraction").at("mean").get<double>() == Approx(retained));
  }
  const auto jobs = service.get("/api/jobs");
  REQUIRE_FALSE(jobs.at("items").empty());
  CHECK_THAT(jobs.at("items")[0].at("command").get<std::string>(), Catch::Contains("mpirun -np 2"));

  // The file itself: one result per case, fragments stored, and the study resubmitted is not rerun.
  CHECK(count_rows(service.store_file(), "SELECT count(*) FROM results") == 6);
  CHECK(count_rows(service.store_file(), "SELECT count(DISTINCT case_id) FROM fragments") == 6);
  const auto again = submit(service, small_study("end to end", {0.005, 0.02, 0.08}, 2), 200);
  CHECK(again.at("existing_study") == true);
  const auto overlapping = submit(service, small_study("overlapping", {0.02, 0.04}, 2));
  CHECK(overlapping.at("already_done") == 2);
  CHECK(overlapping.at("new_cases") == 2);

  const auto status =
      run_command(std::string(AEROBREAK_BINARY) + " study status --url " + service.url() + " " + std::to_string(study));
  CHECK(status.exit_code == 0);
  CHECK_THAT(status.text, Catch::Contains("6 done") && Catch::Contains("(complete)"));
  const auto table_text = run_command(std::string(AEROBREAK_BINARY) + " study results --url " + service.url() + " " +
                                      std::to_string(study));
  CHECK(table_text.exit_code == 0);
  CHECK_THAT(table_text.text, Catch::Contains("speed: the impact speed, in d/tau") && Catch::Contains("break-up %"));
  CHECK(service.kill(SIGTERM) == 0);
}

TEST_CASE("aerobreak run runs a study to completion and prints the outcome table", "[service]") {
  ScratchDirectory scratch("run");
  const auto study_file = scratch.path() / "tiny.study.json";
  std::ofstream(study_file) << small_study("tiny", {0.01, 0.05}, 2).dump(2);
  const auto store = scratch.path() / "tiny.sqlite";
  const std::string command = std::string(AEROBREAK_BINARY) + " run " + study_file.string() + " --store " +
                              store.string() + " --ranks 2 --port 0";
  const auto first = run_command(command);
  INFO(first.text);
  CHECK(first.exit_code == 0);
  CHECK_THAT(first.text, Catch::Contains("stick %") && Catch::Contains("4 done, 0 failed"));
  CHECK_THAT(first.text, Catch::Contains("retained: ") && Catch::Contains("large strain: "));
  CHECK_THAT(first.text,
             Catch::Contains("speed: the impact speed, in d/tau") && Catch::Contains("Critical speeds in d/tau"));
  // The address printed at the start is dead now, and the output says so and how to serve again.
  CHECK_THAT(first.text, Catch::Contains("is no longer served") &&
                             Catch::Contains("aerobreak serve --store " + store.string()) &&
                             Catch::Contains("--keep-serving"));
  CHECK(count_rows(store, "SELECT count(*) FROM results") == 4);

  // Again: everything is done already, nothing is rerun.
  const auto second = run_command(command, true);
  CHECK(second.exit_code == 0);
  CHECK(count_rows(store, "SELECT count(*) FROM attempts") == 4);

  const auto invalid = run_command(std::string(AEROBREAK_BINARY) + " run " + AEROBREAK_SOURCE_DIR +
                                   "/studies/figure4_impact_n256.case.json --store " + store.string());
  CHECK(invalid.exit_code == 2);
  CHECK_THAT(invalid.text, Catch::Contains("is not a valid study"));
  // A mistyped file name is an invalid input too (README, "Exit status"), not CLI11's 105.
  const auto absent =
      run_command(std::string(AEROBREAK_BINARY) + " run " + (scratch.path() / "tiny.sutdy.json").string());
  CHECK(absent.exit_code == 2);
  CHECK_THAT(absent.text, Catch::Contains("File does not exist"));
}

}  // namespace aerobreak::testing
