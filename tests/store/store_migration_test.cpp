// Migration 2 on a store written by schema version 1 (made here from version 1's own SQL):
// stored results are classified again by what leaves the wall, from their stored fragments,
// without re-running them. Migration 9 on a store of version 8: each case's N read from its document;
// migration 10: a cluster file's N from its results' fragments.
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/store/migrations.hpp"
#include "tests/store/store_support.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

struct StoredFragment {
  int primaries;
  bool on_wall;
  double normal_speed;  // of its window-mean velocity, along the wall normal +z
};

// One result as version 1 stored it: the former class (by the largest fragment's share of the
// primaries), its document and its fragments.
struct FormerResult {
  std::string former_class;
  std::vector<StoredFragment> fragments;
  bool settled = true;
  double threshold = 0.9;
};

Json former_document(const FormerResult& r) {
  Json list = Json::array();
  int total = 0, on_wall = 0;
  for (const auto& f : r.fragments) {
    list.push_back({{"size", f.primaries},
                    {"mass", static_cast<double>(f.primaries)},
                    {"velocity", {0.0, 0.0, f.normal_speed + 0.001}},
                    {"normal_velocity", f.normal_speed + 0.001},
                    {"mean_velocity", {0.0, 0.0, f.normal_speed}},
                    {"on_wall", f.on_wall}});
    total += f.primaries;
    if (f.on_wall) on_wall += f.primaries;
  }
  return {{"format", "aerobreak-impact-result"},
          {"format_version", 1},
          {"case", {{"classification", {{"largest_fragment_share", r.threshold}}}}},
          {"setup", {{"wall_normal", {0.0, 0.0, 1.0}}, {"impact_kinetic_energy", 0.5}}},
          {"run", {{"settled", r.settled}}},
          {"outcome",
           {{"class", r.former_class},
            {"reason", "the former rule"},
            {"thresholds", {{"largest_fragment_share", r.threshold}}},
            {"fragment_count", r.fragments.size()},
            {"mass_fraction_on_wall", static_cast<double>(on_wall) / total}}},
          {"contacts", {{"initial", total - 1}}},
          {"fragments", {{"list", list}}}};
}

// A version-1 store with one study whose case k holds results[k] (grid point impact_speed = k).
void write_version_1_store(const std::filesystem::path& file, const std::vector<FormerResult>& results) {
  SqliteDatabase db(file);
  db.execute(store_migrations()[0].sql);
  db.execute("PRAGMA user_version = 1");
  db.execute(
      "INSERT INTO studies (id, hash, name, document, status, max_attempts, case_wall_time, created_at) "
      "VALUES (1, 'study', 'former', '{}', 'active', 1, 60, 0)");
  for (std::size_t k = 0; k < results.size(); ++k) {
    const auto id = static_cast<std::int64_t>(k + 1);
    const Json document = former_document(results[k]);
    db.prepare(
          "INSERT INTO cases (id, hash, document, status, max_attempts, wall_time_limit, queued_at) "
          "VALUES (?, ?, '{}', 'done', 1, 60, 0)")
        .bind_all(id, "case" + std::to_string(k))
        .run();
    const Json grid_point = {{"impact_speed", static_cast<int>(k)}};
    db.prepare(
          "INSERT INTO study_cases (study_id, case_id, position, grid_point, grid_key, replicate) "
          "VALUES (1, ?, ?, ?, ?, 0)")
        .bind_all(id, id, grid_point.dump(), grid_point.dump())
        .run();
    db.prepare(
          "INSERT INTO results (case_id, attempt, outcome, fragment_count, mass_fraction_on_wall, document, "
          "committed_at) VALUES (?, 1, ?, ?, ?, ?, 0)")
        .bind_all(id, results[k].former_class, results[k].fragments.size(),
                  document["outcome"]["mass_fraction_on_wall"].get<double>(), document.dump())
        .run();
    int rank = 0;
    for (const auto& f : results[k].fragments)
      db.prepare(
            "INSERT INTO fragments (case_id, rank, primaries, mass, on_wall, normal_velocity) VALUES (?, ?, ?, ?, ?, "
            "?)")
          .bind_all(id, rank++, f.primaries, static_cast<double>(f.primaries), f.on_wall ? 1 : 0,
                    f.normal_speed + 0.001)
          .run();
  }
}

}  // namespace

TEST_CASE("Migration 2 classifies the results of a version-1 store again by what leaves the wall", "[store]") {
  testing::TemporaryStoreFile file("migration-2");
  const std::vector<FormerResult> former{
      {"break-up", {{60, true, 0.0}, {30, true, 0.0}, {10, true, 0.0}}},  // torn on the wall: now a stick
      {"stick", {{99, true, 0.0}, {1, false, 0.02}}},                     // a monomer left: now a break-up
      {"bounce", {{100, false, 0.3}}},                                    // still a bounce
      {"break-up", {{85, false, 0.1}, {15, false, 0.2}}},                 // still a break-up
      {"stick", {{100, true, 0.0}}, false},                               // the time limit came first
      {"bounce", {{85, false, 0.1}, {15, true, 0.0}}, true, 0.8},         // the case's own bounce share
      {"bounce", {{85, false, 0.1}, {15, true, 0.0}}, true, 0.3},         // a share the rule refuses: 0.9
  };
  write_version_1_store(file.path(), former);

  Store store(file.path());
  CHECK(store.opened_at_version() == 1);
  CHECK(store.schema_version() == latest_store_version());
  const auto page = store.results(1, std::nullopt, {});
  REQUIRE(page.items.size() == former.size());
  const auto& r = page.items;
  CHECK(r[0].outcome == "stick");
  CHECK(r[0].fractured_on_wall == true);
  CHECK(r[0].retained_mass_fraction == Approx(1.0));
  CHECK(r[1].outcome == "break-up");
  CHECK(r[1].retained_mass_fraction == Approx(0.99));
  CHECK(r[1].reentrained_mass_fraction == Approx(0.01));
  CHECK(r[1].fractured_on_wall == false);
  CHECK(r[2].outcome == "bounce");
  CHECK(r[2].retained_mass_fraction == Approx(0.0));
  CHECK(r[3].outcome == "break-up");
  CHECK(r[4].outcome == "undetermined");
  CHECK(r[5].outcome == "bounce");
  CHECK(r[6].outcome == "break-up");
  for (const auto& result : r) {
    INFO("case " << result.case_id);
    CHECK_FALSE(result.damage_ratio);           // not recorded by version 1
    CHECK_FALSE(result.small_strain_exceeded);  // not checked by version 1
    CHECK_FALSE(result.energy_per_contact);
    CHECK(result.initial_contacts == 99);
  }

  // The documents say the same, with the fragments that left and the former class.
  const auto monomer = store.case_detail(2);
  REQUIRE(monomer);
  REQUIRE(monomer->result);
  const Json& outcome = (*monomer->result)["outcome"];
  CHECK(outcome["class"] == "break-up");
  CHECK(outcome["reclassified_from"] == "stick");
  CHECK_FALSE(outcome.contains("mass_fraction_on_wall"));
  CHECK(outcome["retained_mass_fraction"].get<double>() == Approx(0.99));
  CHECK(outcome["damage_ratio"].is_null());
  REQUIRE(outcome["reentrained_fragments"].size() == 1);
  CHECK(outcome["reentrained_fragments"][0]["primaries"] == 1);
  CHECK(outcome["reentrained_fragments"][0]["normal_velocity"].get<double>() == Approx(0.02));  // the window mean
  CHECK((*store.case_detail(7)->result)["outcome"]["thresholds"]["largest_fragment_share"] == 0.9);

  const auto cells = store.outcomes(1);
  REQUIRE(cells.size() == former.size());
  CHECK(cells[0].fractured_on_wall == 1);
  CHECK(cells[0].small_strain_unchecked == 1);
  CHECK(cells[0].small_strain_exceeded == 0);
  CHECK(mean_estimate(store.grid_statistics(1)[1].retained_mass_fraction)->mean == Approx(0.99));
}

TEST_CASE("A migrated store is not migrated again when reopened", "[store]") {
  testing::TemporaryStoreFile file("migration-2-reopen");
  write_version_1_store(file.path(), {{"break-up", {{60, true, 0.0}, {40, true, 0.0}}}});
  std::string document;
  {
    Store store(file.path());
    document = store.case_detail(1)->result->dump();
  }
  Store store(file.path());
  CHECK(store.opened_at_version() == latest_store_version());
  CHECK(store.case_detail(1)->result->dump() == document);
  CHECK((*store.case_detail(1)->result)["outcome"]["reclassified_from"] == "break-up");
}

namespace {

// A version-8 store (made by this aerobreak's own first eight steps) with one study whose case k
// has documents[k] and, for case 1, a result.
void write_version_8_store(const std::filesystem::path& file, const std::vector<std::string>& documents) {
  SqliteDatabase db(file);
  migrate_store(db, store_migrations().first(8));
  db.execute(
      "INSERT INTO studies (id, hash, name, document, status, max_attempts, case_wall_time, created_at) "
      "VALUES (1, 'study', 'former', '{}', 'active', 1, 60, 0)");
  for (std::size_t k = 0; k < documents.size(); ++k) {
    const auto id = static_cast<std::int64_t>(k + 1);
    db.prepare(
          "INSERT INTO cases (id, hash, document, status, max_attempts, wall_time_limit, queued_at) "
          "VALUES (?, ?, ?, 'done', 1, 60, 0)")
        .bind_all(id, "case" + std::to_string(k), documents[k])
        .run();
    const Json grid_point = {{"point", static_cast<int>(k)}};
    db.prepare(
          "INSERT INTO study_cases (study_id, case_id, position, grid_point, grid_key, replicate) "
          "VALUES (1, ?, ?, ?, ?, 0)")
        .bind_all(id, id, grid_point.dump(), grid_point.dump())
        .run();
  }
  db.execute(
      "INSERT INTO results (case_id, attempt, outcome, fragment_count, retained_mass_fraction, document, "
      "committed_at) VALUES (1, 1, 'stick', 1, 1.0, '{}', 0)");
}

}  // namespace

TEST_CASE("Migration 9 stores each case's N, read from its document", "[store]") {
  testing::TemporaryStoreFile file("migration-9");
  write_version_8_store(file.path(), {R"({"cluster": {"generator": {"method": "ballistic", "primaries": 32}}})",
                                      R"({"cluster": {"generator": {"primaries": 64.0}}})",
                                      R"({"cluster": {"file": {"path": "cluster.h5"}}})", "not JSON"});
  {
    Store store(file.path());
    CHECK(store.opened_at_version() == 8);
    CHECK(store.schema_version() == latest_store_version());
    // The statistics read it with the outcomes.
    const auto outcomes = store.study_outcomes(1);
    REQUIRE(outcomes.table.cases.size() == 1);
    CHECK(outcomes.table.cases[0].primaries == 32);
  }
  SqliteDatabase db(file.path());
  auto cases = db.prepare("SELECT primaries FROM cases ORDER BY id");
  std::vector<std::optional<std::int64_t>> primaries;
  while (cases.step()) primaries.push_back(cases.optional_integer(0));
  CHECK(primaries ==
        std::vector<std::optional<std::int64_t>>{32, 64, std::nullopt, std::nullopt});  // a file: its N is the file's
}

TEST_CASE("A case's N is stored with it when its study is submitted", "[store]") {
  testing::TemporaryStoreFile file("case-primaries");
  Store store(file.path());
  auto study = testing::submission("study", "case", {1.0, 2.0});
  study.cases[0].document["cluster"] = {{"generator", {{"method", "dlca"}, {"primaries", 128}}}};
  study.cases[1].document["cluster"] = {{"file", {{"path", "cluster.xyz"}}}};
  const auto receipt = store.submit_study(study);
  const auto points = store.grid_point_cases(receipt.study_id);
  REQUIRE(points.size() == 2);
  CHECK(points[0].primaries == 128);
  CHECK_FALSE(points[1].primaries);
}

TEST_CASE("A cluster file's N is stored with its first result, from the fragments", "[store]") {
  testing::TemporaryStoreFile file("cluster-file-primaries");
  Store store(file.path());
  auto study = testing::submission("study", "case", {1.0});
  study.cases[0].document["cluster"] = {{"file", {{"path", "cluster.xyz"}}}};
  const auto receipt = store.submit_study(study);
  CHECK_FALSE(store.grid_point_cases(receipt.study_id)[0].primaries);
  const auto claimed = store.claim_next_case(store.start_job("test", 1));
  REQUIRE(claimed);
  REQUIRE(store.commit_result(claimed->case_id, claimed->attempt, testing::result_document("break-up", {20, 9, 3}), "",
                              1.0));
  CHECK(store.grid_point_cases(receipt.study_id)[0].primaries == 32);
  REQUIRE(store.study_outcomes(receipt.study_id).table.cases.size() == 1);
  CHECK(store.study_outcomes(receipt.study_id).table.cases[0].primaries == 32);
}

TEST_CASE("Migration 10 stores a cluster file's N from its results and drops the fits made without it", "[store]") {
  testing::TemporaryStoreFile file("migration-10");
  {
    write_version_8_store(file.path(), {R"({"cluster": {"file": {"path": "cluster.h5"}}})",
                                        R"({"cluster": {"file": {"path": "other.h5"}}})"});
    SqliteDatabase db(file.path());
    migrate_store(db, store_migrations().first(9));
    db.execute(
        "INSERT INTO fragments (case_id, rank, primaries, mass, on_wall) VALUES (1, 0, 24, 24.0, 1), "
        "(1, 1, 8, 8.0, 0);"
        "INSERT INTO correlation_sets (id, study_id, request, result_set_version, result_set_hash, "
        "aerobreak_version, computed_at, fit_seconds, summary) VALUES (1, 1, '{}', 1, 'h', 'v', 0, 0, '{}');"
        "INSERT INTO correlation_fits (set_id, name, kind, status, document) VALUES (1, 'f', 'k', 'ok', '{}')");
  }
  SqliteDatabase db(file.path());
  // Up to 10 only: migration 11 drops every stored set (the one shape of a mean).
  CHECK(migrate_store(db, store_migrations().first(10)) == 9);
  auto cases = db.prepare("SELECT primaries FROM cases ORDER BY id");
  std::vector<std::optional<std::int64_t>> primaries;
  while (cases.step()) primaries.push_back(cases.optional_integer(0));
  CHECK(primaries == std::vector<std::optional<std::int64_t>>{32, std::nullopt});  // the second has no result
  auto sets = db.prepare("SELECT (SELECT count(*) FROM correlation_sets), (SELECT count(*) FROM correlation_fits)");
  REQUIRE(sets.step());
  CHECK(sets.integer(0) == 0);
  CHECK(sets.integer(1) == 0);
}

}  // namespace aerobreak
