// What a file named as a store may be, on real SQLite files: another program's database, a file
// that is not SQLite and a newer aerobreak's store are refused unchanged, with advice that can
// work; and a store keeps its data-file paths relative to its data folder (migration 8), so that
// it can move with it, and keeps a result whose file is recomputed until the new one replaces it.
#include <sqlite3.h>

#include <fstream>
#include <iterator>
#include <string>

#include "orchestrator/store/data_paths.hpp"
#include "orchestrator/store/migrations.hpp"
#include "orchestrator/store/store_file.hpp"
#include "tests/store/store_support.hpp"

namespace aerobreak {
namespace {

std::string bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Nothing of the file or beside it changed: the same bytes, no journal, WAL or lock file.
void check_untouched(const std::filesystem::path& file, const std::string& bytes) {
  CHECK(bytes_of(file) == bytes);
  for (const char* suffix : {"-wal", "-shm", "-journal", ".lock"})
    CHECK_FALSE(std::filesystem::exists(file.string() + suffix));
}

// One done case of a study, its result committed with `data_file`.
std::int64_t commit_one(Store& store, const std::string& data_file) {
  store.submit_study(testing::submission("s", "c", {0.1}));
  const auto job = store.start_job("test", 1);
  const auto claimed = store.claim_next_case(job);
  REQUIRE(claimed);
  const auto result = testing::result_document("stick", {4});
  REQUIRE(store.commit_result(claimed->case_id, claimed->attempt, result, data_file, 1.0));
  return claimed->case_id;
}

std::string stored_data_file(const std::filesystem::path& store_file, std::int64_t case_id) {
  SqliteDatabase db(store_file, SqliteDatabase::Mode::read_only);
  auto row = db.prepare("SELECT data_file FROM results WHERE case_id = ?");
  row.bind_all(case_id);
  REQUIRE(row.step());
  return row.text(0);
}

}  // namespace

TEST_CASE("Another program's SQLite database is refused as a store, and left unchanged", "[store]") {
  testing::TemporaryStoreFile file("foreign");
  {
    SqliteDatabase db(file.path());
    db.execute("CREATE TABLE addresses (name TEXT, street TEXT); INSERT INTO addresses VALUES ('a', 'b')");
  }
  const std::string bytes = bytes_of(file.path());
  CHECK(inspect_store_file(file.path()).kind == StoreFileState::Kind::foreign);
  CHECK_THROWS_WITH(Store(file.path()), Catch::Contains("is an SQLite database of another program, not an aerobreak "
                                                        "store") &&
                                            Catch::Contains("addresses"));
  CHECK_THROWS_AS(Store(file.path(), Store::Access::reader), StoreFileRefused);
  check_untouched(file.path(), bytes);
}

TEST_CASE("A file that is not SQLite is refused as a store, and left unchanged", "[store]") {
  testing::TemporaryStoreFile file("text");
  std::ofstream(file.path()) << "name,street\na,b\n";
  const std::string bytes = bytes_of(file.path());
  CHECK_THROWS_WITH(Store(file.path()), Catch::Contains("is not an SQLite database, nor empty"));
  check_untouched(file.path(), bytes);
}

TEST_CASE("A newer aerobreak's store is refused, not misread, with advice that can work, by writer and reader",
          "[store]") {
  testing::TemporaryStoreFile file("newer");
  { Store store(file.path()); }
  {
    SqliteDatabase db(file.path());
    db.execute("PRAGMA user_version = " + std::to_string(latest_store_version() + 1));
  }
  const std::string bytes = bytes_of(file.path());
  for (const auto access : {Store::Access::orchestrator, Store::Access::reader}) {
    try {
      Store store(file.path(), access);
      FAIL("a newer store was opened");
    } catch (const StoreFileRefused& error) {
      const std::string message = error.what();
      CHECK_THAT(message, Catch::Contains("store of a newer aerobreak (schema version " +
                                          std::to_string(latest_store_version() + 1)));
      CHECK_THAT(message, !Catch::Contains("upgrade"));
    }
  }
  CHECK(bytes_of(file.path()) == bytes);
}

TEST_CASE("An empty file becomes a store", "[store]") {
  testing::TemporaryStoreFile file("empty");
  std::ofstream(file.path()).close();
  Store store(file.path());
  CHECK(store.schema_version() == latest_store_version());
}

TEST_CASE("Data-file paths are kept relative to the data folder, and a moved store finds its files", "[store]") {
  testing::TemporaryStoreFile file("relative");
  const auto data = file.path().parent_path() / "first.data";
  std::int64_t case_id = 0;
  {
    Store store(file.path(), Store::Access::orchestrator, data);
    case_id = commit_one(store, (data / "cases" / "c.h5").string());
    CHECK(*store.case_detail(case_id)->data_file == (data / "cases" / "c.h5").string());
  }
  CHECK(stored_data_file(file.path(), case_id) == "cases/c.h5");
  // The same store with its data folder elsewhere (moved, or copied with it).
  const auto moved = file.path().parent_path() / "moved.data";
  Store store(file.path(), Store::Access::reader, moved);
  CHECK(*store.case_detail(case_id)->data_file == (moved / "cases" / "c.h5").string());
  CHECK(store.data_files({"c/{\"impact_speed\":0.1}/0"}).at(0).path == (moved / "cases" / "c.h5").string());
}

TEST_CASE("Migration 8 makes the absolute data-file paths of a version-7 store relative", "[store]") {
  testing::TemporaryStoreFile file("migration-8");
  {
    SqliteDatabase db(file.path());
    migrate_store(db, store_migrations().first(7));
    db.execute(
        "INSERT INTO studies (id, hash, name, document, status, max_attempts, case_wall_time, created_at) "
        "VALUES (1, 'study', 'old', '{}', 'active', 1, 60, 0)");
    for (const int id : {1, 2}) {
      db.prepare(
            "INSERT INTO cases (id, hash, document, status, max_attempts, wall_time_limit, queued_at) "
            "VALUES (?, ?, '{}', 'done', 1, 60, 0)")
          .bind_all(id, "hash" + std::to_string(id))
          .run();
      db.prepare(
            "INSERT INTO results (case_id, attempt, outcome, document, committed_at, data_file) "
            "VALUES (?, 1, 'stick', '{}', 0, ?)")
          .bind_all(id, id == 1 ? "/old/place/store.data/cases/hash1.h5" : "/elsewhere/other.h5")
          .run();
    }
  }
  const auto data = file.path().parent_path() / "store.data";
  Store store(file.path(), Store::Access::orchestrator, data);
  CHECK(store.opened_at_version() == 7);
  CHECK(stored_data_file(file.path(), 1) == "cases/hash1.h5");
  CHECK(store.data_files({"hash1"}).at(0).path == (data / "cases" / "hash1.h5").string());
  // A path that is not the data folder's layout is kept as it was.
  CHECK(stored_data_file(file.path(), 2) == "/elsewhere/other.h5");
}

TEST_CASE("A result whose data file is recomputed stays until the new result replaces it", "[store]") {
  testing::TemporaryStoreFile file("recompute");
  Store store(file.path());
  const std::int64_t case_id = commit_one(store, (store.data_directory() / "cases" / "c.h5").string());
  auto again = testing::submission("s", "c", {0.1});
  again.recompute = {again.cases.front().hash};
  CHECK(store.submit_study(again).recomputed == 1);
  CHECK(store.case_detail(case_id)->result);
  CHECK(store.results(1, std::nullopt, {10, 0}).items.size() == 1);

  const auto job = store.start_job("test", 1);
  const auto claimed = store.claim_next_case(job);
  REQUIRE(claimed);
  REQUIRE(store.commit_result(claimed->case_id, claimed->attempt, testing::result_document("bounce", {4}), "", 1.0));
  CHECK(store.results(1, std::nullopt, {10, 0}).items.size() == 1);
  CHECK(store.case_detail(case_id)->result->at("outcome").at("class") == "bounce");
  CHECK(store.outcomes(1).at(0).outcomes.at("bounce") == 1);
  CHECK(store.outcomes(1).at(0).outcomes.at("stick") == 0);
}

TEST_CASE("Data paths: relative under the data folder, as given elsewhere", "[store]") {
  CHECK(stored_data_path("/a/b.data", "/a/b.data/cases/x.h5") == "cases/x.h5");
  CHECK(stored_data_path("/a/b.data", "/a/other/x.h5") == "/a/other/x.h5");
  CHECK(stored_data_path("/a/b.data", "/a/b.data2/x.h5") == "/a/b.data2/x.h5");
  CHECK(data_path_on_disk("/c/d.data", "cases/x.h5") == "/c/d.data/cases/x.h5");
  CHECK(data_path_on_disk("/c/d.data", "/a/other/x.h5") == "/a/other/x.h5");
  CHECK(default_data_directory("runs/default.sqlite") == "runs/default.data");
}

}  // namespace aerobreak
