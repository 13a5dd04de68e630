// The summaries the store keeps per study and per grid point (store_summaries.hpp) against the same
// figures aggregated from the cases and results themselves, after every kind of transition, across
// studies sharing cases, and through migrations that rewrite results or re-create their table.
#include <string>
#include <vector>

#include "orchestrator/store/migrations.hpp"
#include "orchestrator/store/store_summaries.hpp"
#include "tests/store/store_support.hpp"

namespace aerobreak {
namespace {

// Every row of a query, each as its columns' text joined by " | " (NULL as "null").
std::vector<std::string> rows(SqliteDatabase& db, const std::string& sql) {
  auto statement = db.prepare(sql);
  std::vector<std::string> out;
  while (statement.step()) {
    std::string row;
    for (int k = 0; k < statement.column_count(); ++k)
      row += (k ? " | " : "") + (statement.is_null(k) ? std::string("null") : statement.text(k));
    out.push_back(row);
  }
  return out;
}

// What the summaries must hold, aggregated over all cases and results in the plainest SQL.
constexpr const char* kStudiesFromCases =
    "SELECT s.id, sum(c.status = 'queued'), sum(c.status = 'running'), sum(c.status = 'done'), "
    "sum(c.status = 'failed'), sum(c.status = 'cancelled'), min(c.started_at), max(c.finished_at), "
    "sum(c.status IN ('done', 'failed') AND c.finished_at >= s.created_at) "
    "FROM studies s JOIN study_cases sc ON sc.study_id = s.id JOIN cases c ON c.id = sc.case_id "
    "GROUP BY s.id ORDER BY s.id";
constexpr const char* kStudiesKept =
    "SELECT study_id, queued, running, done, failed, cancelled, first_started_at, last_finished_at, finished_here "
    "FROM study_summaries ORDER BY study_id";
constexpr const char* kGridPointsFromCases =
    "SELECT sc.study_id, sc.grid_key, min(sc.position), count(*), sum(r.outcome IS 'stick'), sum(r.outcome IS "
    "'bounce'), "
    "sum(r.outcome IS 'break-up'), sum(r.outcome IS 'undetermined'), sum(c.status = 'failed') "
    "FROM study_cases sc JOIN cases c ON c.id = sc.case_id LEFT JOIN results r ON r.case_id = c.id "
    "GROUP BY sc.study_id, sc.grid_key ORDER BY sc.study_id, sc.grid_key";
constexpr const char* kGridPointsKept =
    "SELECT study_id, grid_key, position, cases, stick, bounce, break_up, undetermined, failed "
    "FROM grid_point_summaries ORDER BY study_id, grid_key";

void check_summaries(SqliteDatabase& db) {
  CHECK(rows(db, kStudiesKept) == rows(db, kStudiesFromCases));
  CHECK(rows(db, kGridPointsKept) == rows(db, kGridPointsFromCases));
}

void check_summaries(const std::filesystem::path& file) {
  SqliteDatabase db(file, SqliteDatabase::Mode::read_only);
  check_summaries(db);
}

ClaimedCase claim(Store& store, std::int64_t job) {
  auto claimed = store.claim_next_case(job);
  REQUIRE(claimed);
  return *claimed;
}

void commit(Store& store, const ClaimedCase& claimed, const std::string& outcome) {
  REQUIRE(store.commit_result(claimed.case_id, claimed.attempt, testing::result_document(outcome, {4}), "", 1.0));
}

}  // namespace

TEST_CASE("Summaries follow commits, failures, requeues, cancels and resubmissions of shared cases", "[store]") {
  testing::TemporaryStoreFile file("summaries_transitions");
  Store store(file.path());
  const auto first = store.submit_study(testing::submission("s1", "shared", {0.1, 0.2, 0.3}, 2));
  const auto second = store.submit_study(testing::submission("s2", "shared", {0.3, 0.4}, 2, 2));
  check_summaries(file.path());
  const auto job = store.start_job("test", 2);

  SECTION("commits and failures, with attempts left and without") {
    commit(store, claim(store, job), "stick");
    commit(store, claim(store, job), "break-up");
    check_summaries(file.path());
    const auto failing = claim(store, job);
    CHECK(store.record_failure(failing.case_id, failing.attempt, AttemptEnd::error, "x") == CaseStatus::queued);
    check_summaries(file.path());
    const auto again = claim(store, job);
    CHECK(again.case_id == failing.case_id);
    CHECK(store.record_failure(again.case_id, again.attempt, AttemptEnd::invalid, "bad") == CaseStatus::failed);
    check_summaries(file.path());
    // A case both studies share (speed 0.3): done for both.
    for (int k = 0; k < 3; ++k) commit(store, claim(store, job), k == 1 ? "bounce" : "undetermined");
    check_summaries(file.path());
    CHECK(store.progress(second.study_id)->by_status.at("done") == 2);
  }
  SECTION("a lost job and an interrupted orchestrator") {
    claim(store, job);
    claim(store, job);
    CHECK(store.requeue_job(job, "lost") == 2);
    check_summaries(file.path());
    const auto next_job = store.start_job("test", 1);
    claim(store, next_job);
    CHECK(store.requeue_interrupted() == 1);
    check_summaries(file.path());
  }
  SECTION("cancel and resubmission") {
    commit(store, claim(store, job), "stick");
    const auto running = claim(store, job);
    REQUIRE(store.cancel_study(first.study_id));
    check_summaries(file.path());
    // Speed 0.3 is wanted by the second study: those cases stay queued.
    CHECK(store.progress(first.study_id)->by_status.at("cancelled") == 2);
    // The running case finishes after the cancel; the resubmission queues the cancelled ones again.
    commit(store, running, "bounce");
    const auto resubmitted = store.submit_study(testing::submission("s1", "shared", {0.1, 0.2, 0.3}, 2));
    CHECK(resubmitted.requeued == 2);
    check_summaries(file.path());
    // A requeued case that fails with attempts left loses the finish time its cancel gave it; the
    // last one of the study (a cancel's) is looked up again.
    const auto retried = claim(store, job);
    CHECK(store.record_failure(retried.case_id, retried.attempt, AttemptEnd::error, "x") == CaseStatus::queued);
    check_summaries(file.path());
  }
  SECTION("a third study joining cases that are finished, failed and running") {
    commit(store, claim(store, job), "stick");
    const auto failing = claim(store, job);
    store.record_failure(failing.case_id, failing.attempt, AttemptEnd::invalid, "bad");
    claim(store, job);
    store.submit_study(testing::submission("s3", "shared", {0.1, 0.2}, 2));
    check_summaries(file.path());
  }
  store.rebuild_summaries();
  check_summaries(file.path());
}

TEST_CASE("Progress and outcomes read from the summaries give the figures of the cases", "[store]") {
  testing::TemporaryStoreFile file("summaries_reads");
  Store store(file.path());
  const auto study = store.submit_study(testing::submission("s1", "c", {0.1, 0.2}, 3));
  const auto job = store.start_job("test", 1);
  for (const char* outcome : {"stick", "bounce", "bounce", "break-up"}) commit(store, claim(store, job), outcome);
  const auto failing = claim(store, job);
  store.record_failure(failing.case_id, failing.attempt, AttemptEnd::invalid, "bad");
  const auto progress = store.progress(study.study_id);
  REQUIRE(progress);
  CHECK(progress->total == 6);
  CHECK(progress->by_status.at("done") == 4);
  CHECK(progress->by_status.at("failed") == 1);
  CHECK(progress->by_status.at("queued") == 1);
  CHECK(store.study(study.study_id)->case_count == 6);
  const auto cells = store.outcomes(study.study_id);
  REQUIRE(cells.size() == 2);
  CHECK(cells[0].grid_point.at("impact_speed") == 0.1);
  CHECK(cells[0].outcomes.at("bounce") == 2);
  CHECK(cells[1].outcomes.at("break-up") == 1);
  CHECK(cells[1].failed == 1);
  CHECK(cells[1].cases == 3);
}

TEST_CASE("A study's versions change with what they stand for, and with nothing else", "[store]") {
  testing::TemporaryStoreFile file("summaries_versions");
  Store store(file.path());
  const auto first = store.submit_study(testing::submission("s1", "a", {0.1, 0.2}));
  const auto other = store.submit_study(testing::submission("s2", "b", {0.1}));
  const auto job = store.start_job("test", 1);
  const auto before = *store.study_versions(first.study_id);
  const auto other_before = *store.study_versions(other.study_id);
  CHECK_FALSE(store.study_versions(other.study_id + 1));

  const auto claimed = claim(store, job);
  const auto after_claim = *store.study_versions(first.study_id);
  CHECK(after_claim.case_states > before.case_states);
  CHECK(after_claim.result_set == before.result_set);
  store.record_worker(claimed.case_id, claimed.attempt, "host:0");
  CHECK(store.study_versions(first.study_id)->case_states == after_claim.case_states);

  commit(store, claimed, "stick");
  const auto after_commit = *store.study_versions(first.study_id);
  CHECK(after_commit.result_set > after_claim.result_set);
  CHECK(after_commit.case_states > after_claim.case_states);
  // Nothing of the other study changed.
  CHECK(store.study_versions(other.study_id)->result_set == other_before.result_set);
  CHECK(store.study_versions(other.study_id)->case_states == other_before.case_states);

  // A study that joins a finished case has a result set from the start; the rebuild raises both.
  const auto joining = store.submit_study(testing::submission("s3", "a", {0.1}));
  const auto joined = *store.study_versions(joining.study_id);
  CHECK(joined.result_set >= 1);
  store.rebuild_summaries();
  CHECK(store.study_versions(joining.study_id)->result_set > joined.result_set);
  CHECK(store.study_versions(joining.study_id)->case_states > joined.case_states);
}

TEST_CASE("A migration that re-classifies outcomes, or re-creates a table, leaves the summaries right", "[store]") {
  testing::TemporaryStoreFile file("summaries_migration");
  std::int64_t study_id = 0;
  {
    Store store(file.path());
    study_id = store.submit_study(testing::submission("s1", "c", {0.1, 0.2}, 2)).study_id;
    const auto job = store.start_job("test", 1);
    for (const char* outcome : {"stick", "stick", "bounce"}) commit(store, claim(store, job), outcome);
  }
  SqliteDatabase db(file.path());
  const int latest = latest_store_version();
  std::vector<Migration> steps(store_migrations().begin(), store_migrations().end());
  // Like the outcomes migration: rewrite results.outcome by SQL.
  steps.push_back({latest + 1, "re-classify", "UPDATE results SET outcome = 'break-up' WHERE outcome = 'stick'"});
  // A step that re-creates a table drops its triggers with it, and one that changes links changes
  // what no trigger follows: the rebuild after the step puts the triggers back and recomputes.
  steps.push_back({latest + 2, "re-create study_cases, merge grid points",
                   "CREATE TABLE study_cases_copy AS SELECT * FROM study_cases;"
                   "DROP TABLE study_cases;"
                   "ALTER TABLE study_cases_copy RENAME TO study_cases;"
                   "UPDATE study_cases SET grid_key = 'all', grid_point = '{}';"
                   "UPDATE results SET outcome = 'undetermined' WHERE outcome = 'bounce';"});
  CHECK(migrate_store(db, steps) == latest);
  check_summaries(db);
  auto counts =
      db.prepare("SELECT sum(stick), sum(bounce), sum(break_up), sum(undetermined) FROM grid_point_summaries");
  REQUIRE(counts.step());
  CHECK(counts.integer(0) == 0);
  CHECK(counts.integer(1) == 0);
  CHECK(counts.integer(2) == 2);
  CHECK(counts.integer(3) == 1);
  CHECK(rows(db, "SELECT grid_key, cases FROM grid_point_summaries") == std::vector<std::string>{"all | 4"});
  // The triggers are back: later changes are followed again.
  db.execute("UPDATE results SET outcome = 'stick' WHERE outcome = 'undetermined'");
  db.execute(
      "INSERT INTO studies (id, hash, name, document, status, max_attempts, case_wall_time, created_at) "
      "VALUES (" +
      std::to_string(study_id + 1) + ", 'later', 'later', '{}', 'active', 3, 60, 0)");
  db.execute("INSERT INTO study_cases (study_id, case_id, position, grid_point, grid_key, replicate) SELECT " +
             std::to_string(study_id + 1) + ", case_id, position, grid_point, 'later', replicate FROM study_cases");
  check_summaries(db);
}

TEST_CASE("A store made before the summaries gets them when opened", "[store]") {
  testing::TemporaryStoreFile file("summaries_upgrade");
  {
    SqliteDatabase db(file.path());
    migrate_store(db, store_migrations().first(1));
    db.execute(R"sql(
      INSERT INTO studies (id, hash, name, document, status, max_attempts, case_wall_time, created_at)
        VALUES (1, 'h', 'old', '{}', 'active', 3, 60, 100);
      INSERT INTO cases (id, hash, document, status, max_attempts, wall_time_limit, queued_at, started_at, finished_at)
        VALUES (1, 'a', '{}', 'done', 3, 60, 100, 110, 120), (2, 'b', '{}', 'failed', 3, 60, 100, 111, 130),
               (3, 'c', '{}', 'queued', 3, 60, 100, NULL, NULL);
      INSERT INTO study_cases (study_id, case_id, position, grid_point, grid_key, replicate)
        VALUES (1, 1, 0, '{"v":1}', 'k1', 0), (1, 2, 1, '{"v":1}', 'k1', 1), (1, 3, 2, '{"v":2}', 'k2', 0);
      INSERT INTO results (case_id, attempt, outcome, document, committed_at) VALUES (1, 1, 'bounce', '{}', 120);
    )sql");
  }
  Store store(file.path());
  CHECK(store.opened_at_version() == 1);
  check_summaries(file.path());
  const auto progress = store.progress(1);
  REQUIRE(progress);
  CHECK(progress->by_status.at("done") == 1);
  CHECK(progress->by_status.at("failed") == 1);
  CHECK(progress->by_status.at("queued") == 1);
  CHECK(progress->first_started_at == 110.0);
  CHECK(progress->last_finished_at == 130.0);
  const auto cells = store.outcomes(1);
  REQUIRE(cells.size() == 2);
  CHECK(cells[0].outcomes.at("bounce") == 1);
  CHECK(cells[0].failed == 1);
  CHECK(cells[1].cases == 1);
}

}  // namespace aerobreak
