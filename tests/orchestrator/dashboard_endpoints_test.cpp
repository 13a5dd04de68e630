// The dashboard's endpoints over real HTTP on a real store: per-grid-point statistics checked
// against the same numbers computed here from the results, the case table's filters and paging, the
// fragment-size counts, a case's HDF5 file served only from the data folder, and the page's files
// (only those listed, with their Content-Security-Policy).
#include <sqlite3.h>

#include <cmath>
#include <vector>

#include "tests/orchestrator/service_process.hpp"
#include "tests/support/openapi_schema.hpp"

namespace aerobreak::testing {
namespace {

struct Answer {
  int status;
  std::string body;
  httplib::Headers headers;
  Json json() const { return Json::parse(body, nullptr, false); }
};

Answer get(const ServiceProcess& service, const std::string& path) {
  auto client = service.client();
  const auto response = client.Get(path.c_str());
  REQUIRE(response);
  return {response->status, response->body, response->headers};
}

void execute(const std::filesystem::path& file, const std::string& sql) {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(file.c_str(), &db) == SQLITE_OK);
  sqlite3_busy_timeout(db, 5000);
  CHECK(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(db);
}

// The finished study every section reads: 3 speeds x 3 replicates of 8 primaries.
std::int64_t finished_study(const ServiceProcess& service) {
  const auto id = submit(service, small_study("dashboard", {0.005, 0.02, 0.3}, 3, 8)).at("id").get<std::int64_t>();
  REQUIRE(eventually([&] { return study_complete(service, id); }, 120s));
  return id;
}

// A grid point's means of the outcome columns and its flag counts, against the results at `speed`.
void check_outcome_columns(const Json& row, const Json& results, double speed) {
  double damage = 0.0, energy = 0.0;
  std::size_t n = 0, fractured = 0, exceeded = 0;
  for (const auto& result : results)
    if (result.at("grid_point").at("impact_speed") == speed) {
      damage += result.at("damage_ratio").get<double>();
      energy += result.at("energy_per_contact").get<double>();
      fractured += result.at("fractured_on_wall").get<bool>();
      exceeded += result.at("small_strain_exceeded").get<bool>();
      ++n;
    }
  REQUIRE(n == 3);
  CHECK(row.at("damage_ratio").at("n") == 3);
  CHECK(row.at("damage_ratio").at("mean").get<double>() == Approx(damage / 3.0));
  CHECK(row.at("energy_per_contact").at("mean").get<double>() == Approx(energy / 3.0));
  CHECK(row.at("fractured_on_wall") == fractured);
  CHECK(row.at("small_strain_exceeded") == exceeded);
  CHECK(row.at("small_strain_unchecked") == 0);
}

}  // namespace

TEST_CASE("Dashboard endpoints: grid statistics, case table, fragment sizes and case files", "[service][dashboard]") {
  ScratchDirectory scratch("dashboard");
  ServiceProcess service(scratch.path());
  const auto id = finished_study(service);
  const std::string study = "/api/studies/" + std::to_string(id);
  const auto results = service.get(study + "/results").at("items");
  REQUIRE(results.size() == 9);

  SECTION("per grid point: outcome counts, and means with Student intervals of the results' quantities") {
    const auto grid = service.get(study + "/grid");
    // One shape of a mean (MeanEstimate) in both documents, as schemas/openapi.json describes them.
    INFO(describe(openapi_component("GridStatistics").validate(grid)));
    CHECK(openapi_component("GridStatistics").validate(grid).empty());
    const auto outcomes = service.get(study + "/outcomes");
    INFO(describe(openapi_component("OutcomeTable").validate(outcomes)));
    CHECK(openapi_component("OutcomeTable").validate(outcomes).empty());
    REQUIRE(grid.at("axes").size() == 1);
    CHECK(grid.at("axes")[0].at("values") == Json::array({0.005, 0.02, 0.3}));
    REQUIRE(grid.at("grid_points").size() == 3);
    for (const auto& row : grid.at("grid_points")) {
      const double speed = row.at("grid_point").at("impact_speed");
      std::vector<double> values;
      for (const auto& result : results)
        if (result.at("grid_point").at("impact_speed") == speed) values.push_back(result.at("retained_mass_fraction"));
      REQUIRE(values.size() == 3);
      const double mean = (values[0] + values[1] + values[2]) / 3.0;
      double squares = 0.0;
      for (const double value : values) squares += (value - mean) * (value - mean);
      const double sd = std::sqrt(squares / 2.0);
      const auto& retained = row.at("retained_mass_fraction");
      CHECK(row.at("finished") == 3);
      CHECK(retained.at("n") == 3);
      CHECK(retained.at("mean").get<double>() == Approx(mean));
      CHECK(retained.at("standard_deviation").get<double>() == Approx(sd).margin(1e-12));
      CHECK(retained.at("standard_error").get<double>() == Approx(sd / std::sqrt(3.0)).margin(1e-12));
      // t(0.975, 2) = 4.3026527 (R: qt(0.975, 2)).
      CHECK(retained.at("ci95")[1].get<double>() == Approx(mean + 4.3026527 * sd / std::sqrt(3.0)).margin(1e-9));
      check_outcome_columns(row, results, speed);
    }
  }

  SECTION("the case table filters by axis value (as a number), outcome and status, and pages") {
    const auto by_speed = service.get(study + "/case-table?axis.impact_speed=2e-2");
    CHECK(by_speed.at("total") == 3);
    for (const auto& row : by_speed.at("items")) CHECK(row.at("grid_point").at("impact_speed") == 0.02);
    const auto stick = service.get(study + "/case-table?outcome=stick&axis.impact_speed=0.02&axis.impact_speed=0.3");
    std::size_t expected = 0;
    for (const auto& result : results)
      expected += result.at("outcome") == "stick" && result.at("grid_point").at("impact_speed") != 0.005;
    CHECK(stick.at("total") == expected);
    CHECK(service.get(study + "/case-table?status=queued").at("total") == 0);
    const auto all = service.get(study + "/case-table");
    const auto last = service.get(study + "/case-table?limit=2&offset=8");
    REQUIRE(last.at("items").size() == 1);
    CHECK(last.at("items")[0].at("id") == all.at("items")[8].at("id"));
    CHECK(all.at("items")[0].contains("retained_mass_fraction"));
    for (const auto& row : all.at("items"))
      for (const auto& result : results)
        if (result.at("case") == row.at("id"))
          for (const char* column :
               {"damage_ratio", "fractured_on_wall", "small_strain_exceeded", "retained_mass_fraction"})
            CHECK(row.at(column) == result.at(column));

    CHECK(get(service, study + "/case-table?axis.friction=0.3").status == 400);
    CHECK_THAT(get(service, study + "/case-table?axis.friction=0.3").body, Catch::Contains("no axis 'friction'"));
    CHECK(get(service, study + "/case-table?status=lost").status == 400);
    std::string many = study + "/case-table?";
    for (int i = 0; i < 65; ++i) many += "axis.impact_speed=" + std::to_string(i) + "&";
    CHECK(get(service, many).status == 400);
  }

  SECTION("fragment sizes count every fragment of the grid points asked for") {
    const auto sizes = service.get(study + "/fragment-sizes?axis.impact_speed=0.3");
    REQUIRE(sizes.at("grid_points").size() == 1);
    const auto& point = sizes.at("grid_points")[0];
    CHECK(point.at("results") == 3);
    long long fragments = 0, primaries = 0;
    for (const auto& size : point.at("sizes")) {
      fragments += size[1].get<long long>();
      primaries += size[0].get<long long>() * size[1].get<long long>();
    }
    long long expected = 0;
    for (const auto& result : results)
      if (result.at("grid_point").at("impact_speed") == 0.3) expected += result.at("fragment_count").get<long long>();
    CHECK(fragments == expected);
    CHECK(primaries == 3 * 8);
  }

  SECTION("a case's HDF5 file, and only from the data folder") {
    const auto answer = get(service, "/api/cases/1/data");
    REQUIRE(answer.status == 200);
    CHECK(answer.body.substr(0, 8) == std::string("\x89HDF\r\n\x1a\n", 8));
    const auto detail = service.get("/api/cases/1");
    CHECK(answer.body.size() == std::filesystem::file_size(detail.at("data_file").get<std::string>()));
    CHECK(get(service, "/api/cases/999999/data").status == 404);
    execute(service.store_file(), "UPDATE results SET data_file = '/etc/passwd' WHERE case_id = 1");
    const auto outside = get(service, "/api/cases/1/data");
    CHECK(outside.status == 404);
    CHECK_THAT(outside.body, Catch::Contains("not in the service's data folder"));
  }

  SECTION("the progress of the newest studies") {
    const auto progress = service.get("/api/progress");
    CHECK(progress.at("total") == 1);
    CHECK(progress.at("items")[0].at("progress").at("counts").at("done") == 9);
    CHECK(get(service, "/api/progress?limit=101").status == 400);
  }

  SECTION("the page's files, with their policy; nothing else of the web folder") {
    const auto page = get(service, "/");
    REQUIRE(page.status == 200);
    CHECK_THAT(page.body, Catch::Contains("<script type=\"module\" src=\"/src/main.js\">"));
    const auto policy = page.headers.find("Content-Security-Policy");
    REQUIRE(policy != page.headers.end());
    CHECK_THAT(policy->second, Catch::Contains("script-src 'self'") && Catch::Contains("default-src 'none'"));
    CHECK(get(service, "/vendor/uPlot.esm.js").status == 200);
    for (const auto* path : {"/node_modules/uplot/dist/uPlot.esm.js", "/package.json", "/vendor.json",
                             "/src/../package-lock.json", "/../CMakeLists.txt"})
      CHECK(get(service, path).status == 404);
  }
}

TEST_CASE("With --web-dir empty the service serves the API only", "[service][dashboard]") {
  ScratchDirectory scratch("no-dashboard");
  ServiceProcess service(scratch.path(), {"--web-dir", ""});
  CHECK(get(service, "/").status == 404);
  CHECK(get(service, "/api/health").status == 200);
}

}  // namespace aerobreak::testing
