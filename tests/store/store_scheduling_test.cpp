// The scheduler's transitions: submission with deduplication, claims, exactly-once commits,
// failures with bounded attempts, lost jobs, an interrupted orchestrator, cancellation.
#include "tests/store/store_support.hpp"

namespace aerobreak {

TEST_CASE("Submitting stores each case once by hash, and the same study again changes nothing", "[store]") {
  testing::TemporaryStoreFile file("submit");
  Store store(file.path());
  const auto first = store.submit_study(testing::submission("s1", "shared", {0.1, 0.2, 0.3}, 2));
  CHECK_FALSE(first.existing_study);
  CHECK(first.cases == 6);
  CHECK(first.new_cases == 6);

  const auto again = store.submit_study(testing::submission("s1", "shared", {0.1, 0.2, 0.3}, 2));
  CHECK(again.existing_study);
  CHECK(again.study_id == first.study_id);
  CHECK(again.new_cases == 0);

  const auto overlapping = store.submit_study(testing::submission("s2", "shared", {0.3, 0.4}, 2));
  CHECK(overlapping.study_id != first.study_id);
  CHECK(overlapping.cases == 4);
  CHECK(overlapping.new_cases == 2);
  CHECK(store.claimable_cases() == 8);
}

TEST_CASE("A finished case is never rerun when another study names it", "[store]") {
  testing::TemporaryStoreFile file("finished");
  Store store(file.path());
  store.submit_study(testing::submission("s1", "shared", {0.1}));
  const auto job = store.start_job("test", 1);
  const auto claimed = store.claim_next_case(job);
  REQUIRE(claimed);
  REQUIRE(store.commit_result(claimed->case_id, claimed->attempt, testing::result_document("stick", {4}), "", 1.0));

  const auto receipt = store.submit_study(testing::submission("s2", "shared", {0.1, 0.2}));
  CHECK(receipt.already_done == 1);
  CHECK(receipt.new_cases == 1);
  CHECK(store.claimable_cases() == 1);
  const auto progress = store.progress(receipt.study_id);
  REQUIRE(progress);
  CHECK(progress->by_status.at("done") == 1);
  CHECK(progress->by_status.at("queued") == 1);
}

TEST_CASE("Claims hand out queued cases in submission order with increasing attempts", "[store]") {
  testing::TemporaryStoreFile file("claim");
  Store store(file.path());
  store.submit_study(testing::submission("s1", "c", {0.1, 0.2}));
  const auto job = store.start_job("test", 2);
  const auto a = store.claim_next_case(job, "host:0");
  const auto b = store.claim_next_case(job, "host:1");
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->case_id < b->case_id);
  CHECK(a->attempt == 1);
  CHECK(a->document.at("impact").at("speed") == 0.1);
  CHECK(a->wall_time_limit == 60.0);
  CHECK_FALSE(store.claim_next_case(job));
}

TEST_CASE("A result is committed exactly once, and only for the running attempt", "[store]") {
  testing::TemporaryStoreFile file("commit");
  Store store(file.path());
  const auto study = store.submit_study(testing::submission("s1", "c", {0.1}));
  const auto job = store.start_job("test", 1);
  const auto claimed = store.claim_next_case(job);
  REQUIRE(claimed);
  const auto result = testing::result_document("break-up", {5, 3});
  CHECK_FALSE(store.commit_result(claimed->case_id, claimed->attempt + 1, result, "", 1.0));
  CHECK(store.commit_result(claimed->case_id, claimed->attempt, result, "/data/a.h5", 1.0));
  CHECK_FALSE(store.commit_result(claimed->case_id, claimed->attempt, result, "/data/a.h5", 1.0));

  const auto page = store.results(study.study_id, std::nullopt, {});
  REQUIRE(page.total == 1);
  CHECK(page.items[0].outcome == "break-up");
  CHECK(page.items[0].fragment_count == 2);
  CHECK(page.items[0].largest_fragment_share == Approx(5.0 / 8.0));
  const auto detail = store.case_detail(claimed->case_id);
  REQUIRE(detail);
  CHECK(detail->fragments.size() == 2);
  CHECK(detail->fragments[1].primaries == 3);
  CHECK(detail->data_file == "/data/a.h5");
}

TEST_CASE("A result without an outcome is refused and leaves the case running", "[store]") {
  testing::TemporaryStoreFile file("bad-result");
  Store store(file.path());
  store.submit_study(testing::submission("s1", "c", {0.1}));
  const auto claimed = store.claim_next_case(store.start_job("test", 1));
  REQUIRE(claimed);
  CHECK_THROWS_AS(store.commit_result(claimed->case_id, claimed->attempt, {{"outcome", {}}}, "", 1.0),
                  std::invalid_argument);
  CHECK(store.case_detail(claimed->case_id)->record.status == "running");
  CHECK(store.commit_result(claimed->case_id, claimed->attempt, testing::result_document("stick", {2}), "", 1.0));
}

TEST_CASE("A failing case is retried until max_attempts, then marked failed with its error", "[store]") {
  testing::TemporaryStoreFile file("poison");
  Store store(file.path());
  store.submit_study(testing::submission("s1", "c", {0.1}, 1, 3));
  const auto job = store.start_job("test", 1);
  for (int attempt = 1; attempt <= 3; ++attempt) {
    const auto claimed = store.claim_next_case(job);
    REQUIRE(claimed);
    CHECK(claimed->attempt == attempt);
    const auto status =
        store.record_failure(claimed->case_id, claimed->attempt, AttemptEnd::error, "boom " + std::to_string(attempt));
    CHECK(status == (attempt < 3 ? CaseStatus::queued : CaseStatus::failed));
  }
  CHECK_FALSE(store.claim_next_case(job));
  const auto detail = store.case_detail(1);
  REQUIRE(detail);
  CHECK(detail->record.status == "failed");
  CHECK(detail->record.error == "boom 3");
  CHECK(detail->attempts.size() == 3);
}

TEST_CASE("An invalid case fails at once: retrying cannot help", "[store]") {
  testing::TemporaryStoreFile file("invalid");
  Store store(file.path());
  store.submit_study(testing::submission("s1", "c", {0.1}, 1, 3));
  const auto claimed = store.claim_next_case(store.start_job("test", 1));
  REQUIRE(claimed);
  CHECK(store.record_failure(claimed->case_id, 1, AttemptEnd::invalid, "/impact/speed: must be > 0") ==
        CaseStatus::failed);
  CHECK_FALSE(store.record_failure(claimed->case_id, 1, AttemptEnd::error, "late"));
}

TEST_CASE("Cases of a lost job are requeued with a failure counted, an interrupted orchestrator counts none",
          "[store]") {
  testing::TemporaryStoreFile file("lost");
  Store store(file.path());
  store.submit_study(testing::submission("s1", "c", {0.1, 0.2}, 1, 2));
  const auto job = store.start_job("test", 2);
  const auto a = store.claim_next_case(job);
  const auto b = store.claim_next_case(job);
  REQUIRE((a && b));
  CHECK(store.commit_result(b->case_id, b->attempt, testing::result_document("stick", {3}), "", 1.0));
  CHECK(store.requeue_job(job, "worker job ended with signal 9") == 1);
  CHECK(store.case_detail(a->case_id)->record.failures == 1);
  CHECK(store.case_detail(b->case_id)->record.status == "done");

  const auto again = store.claim_next_case(store.start_job("test", 1));
  REQUIRE(again);
  CHECK(again->attempt == 2);
  CHECK(store.requeue_interrupted() == 1);
  const auto detail = store.case_detail(a->case_id);
  CHECK(detail->record.status == "queued");
  CHECK(detail->record.failures == 1);
  CHECK(detail->attempts.back().outcome == "interrupted");
  CHECK(store.close_orphaned_jobs() == 2);
}

TEST_CASE("Cancelling a study cancels its queued cases unless another active study wants them", "[store]") {
  testing::TemporaryStoreFile file("cancel");
  Store store(file.path());
  const auto first = store.submit_study(testing::submission("s1", "shared", {0.1, 0.2}));
  const auto second = store.submit_study(testing::submission("s2", "shared", {0.2, 0.3}));
  const auto job = store.start_job("test", 1);
  const auto running = store.claim_next_case(job);
  REQUIRE(running);
  CHECK(store.cancel_study(first.study_id));
  CHECK_FALSE(store.cancel_study(first.study_id));
  const auto progress = store.progress(first.study_id);
  CHECK(progress->by_status.at("running") == 1);
  CHECK(progress->by_status.at("queued") == 1);  // 0.2 is wanted by the second study
  CHECK(store.claimable_cases() == 2);
  CHECK(store.cancel_study(second.study_id));
  CHECK(store.claimable_cases() == 0);
  CHECK(store.commit_result(running->case_id, running->attempt, testing::result_document("stick", {2}), "", 1.0));

  const auto resubmitted = store.submit_study(testing::submission("s2", "shared", {0.2, 0.3}));
  CHECK(resubmitted.existing_study);
  CHECK(resubmitted.requeued == 2);
  CHECK(store.claimable_cases() == 2);
}

}  // namespace aerobreak

namespace aerobreak {

TEST_CASE("A job the orchestrator stopped requeues its cases without counting a failure", "[store]") {
  testing::TemporaryStoreFile file("stopped-job");
  Store store(file.path());
  store.submit_study(testing::submission("s1", "c", {0.1}, 1, 1));
  const auto job = store.start_job("test", 1);
  const auto claimed = store.claim_next_case(job);
  REQUIRE(claimed);
  CHECK(store.requeue_job(job, "killed for another case's wall time", false) == 1);
  const auto detail = store.case_detail(claimed->case_id);
  CHECK(detail->record.status == "queued");
  CHECK(detail->record.failures == 0);
  CHECK(detail->attempts.back().outcome == "interrupted");
  CHECK(detail->attempts.back().error == "killed for another case's wall time");
  CHECK(store.claim_next_case(job)->attempt == 2);
}

}  // namespace aerobreak
