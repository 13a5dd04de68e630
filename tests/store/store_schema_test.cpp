// The store file itself: schema version, migrations, WAL, foreign keys.
#include <sqlite3.h>

#include "orchestrator/store/migrations.hpp"
#include "tests/store/store_support.hpp"

namespace aerobreak {
namespace {

int pragma_integer(SqliteDatabase& db, const std::string& pragma) {
  auto statement = db.prepare("PRAGMA " + pragma);
  REQUIRE(statement.step());
  return static_cast<int>(statement.integer(0));
}

}  // namespace

TEST_CASE("A new store file is created at the latest schema version, in WAL mode", "[store]") {
  testing::TemporaryStoreFile file("new");
  {
    Store store(file.path());
    CHECK(store.opened_at_version() == 0);
    CHECK(store.schema_version() == latest_store_version());
  }
  SqliteDatabase db(file.path());
  auto mode = db.prepare("PRAGMA journal_mode");
  REQUIRE(mode.step());
  CHECK(mode.text(0) == "wal");
  CHECK(pragma_integer(db, "user_version") == latest_store_version());
}

TEST_CASE("Reopening a store keeps its data and does not migrate again", "[store]") {
  testing::TemporaryStoreFile file("reopen");
  std::int64_t study_id = 0;
  {
    Store store(file.path());
    study_id = store.submit_study(testing::submission("s1", "c", {0.1, 0.2})).study_id;
  }
  Store store(file.path());
  CHECK(store.opened_at_version() == latest_store_version());
  const auto study = store.study(study_id);
  REQUIRE(study);
  CHECK(study->case_count == 2);
}

TEST_CASE("Every migration step brings the version to its number, in order", "[store]") {
  int previous = 0;
  for (const auto& step : store_migrations()) {
    CHECK(step.version == previous + 1);
    CHECK_FALSE(step.sql.empty());
    previous = step.version;
  }
  CHECK(previous == latest_store_version());
}

TEST_CASE("The store enforces foreign keys and the case status domain", "[store]") {
  testing::TemporaryStoreFile file("constraints");
  Store store(file.path());
  SqliteDatabase db(file.path());
  CHECK_THROWS_AS(
      db.execute("INSERT INTO fragments (case_id, rank, primaries, mass, on_wall) VALUES (999, 0, 1, 1, 0)"),
      SqliteError);
  CHECK_THROWS_AS(db.execute("INSERT INTO cases (hash, document, status, max_attempts, wall_time_limit, queued_at) "
                             "VALUES ('h', '{}', 'sleeping', 1, 1, 0)"),
                  SqliteError);
}

}  // namespace aerobreak
