// The scheduler in this process over a real store, with worker jobs that are shell scripts
// speaking the line protocol (docs/WORKER_PROTOCOL.md) and then never answering their case, going
// silent, or giving up one of their ranks.
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <regex>
#include <thread>

#include "orchestrator/scheduler/scheduler.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {
namespace {

using namespace std::chrono_literals;

// Says ready with one rank, then sleeps: a case stuck where it cannot check the clock.
constexpr const char* kStuckWorker =
    "#!/bin/sh\n"
    "echo \"@aerobreak {\\\"type\\\":\\\"ready\\\",\\\"ranks\\\":1,\\\"hosts\\\":[\\\"test\\\"],\\\"pid\\\":$$,"
    "\\\"version\\\":\\\"test\\\"}\"\n"
    "exec sleep 600\n";

// Says ready with two ranks, reads one case and reports what rank 0 says of a rank that went silent
// while it ran it (docs/WORKER_PROTOCOL.md, rank_lost), then sleeps, saying nothing more.
constexpr const char* kRankLosingWorker = R"(#!/bin/sh
echo "@aerobreak {\"type\":\"ready\",\"ranks\":2,\"hosts\":[\"a\",\"b\"],\"pid\":$$,\"version\":\"test\"}"
read line
set -- $(echo "$line" | sed -n 's/.*"case":\([0-9]*\),"attempt":\([0-9]*\).*/\1 \2/p')
echo '@aerobreak {"type":"rank_lost","rank":1,"host":"b","ranks":1,"silent_seconds":61}'
echo "@aerobreak {\"type\":\"failed\",\"case\":$1,\"attempt\":$2,\"rank\":1,\"seconds\":61,"\
"\"kind\":\"lost\",\"error\":\"rank 1 went silent\"}"
exec sleep 600
)";

StudySubmission cases_study(double wall_time, int cases, int max_attempts) {
  StudySubmission submission;
  submission.hash = "stuck-study";
  submission.name = "stuck";
  submission.document = nlohmann::ordered_json::object();
  submission.max_attempts = max_attempts;
  submission.case_wall_time = wall_time;
  for (int c = 0; c < cases; ++c)
    submission.cases.push_back({"stuck-case-" + std::to_string(c),
                                nlohmann::ordered_json::object(),
                                {{"impact_speed", 0.01 * (c + 1)}},
                                "k" + std::to_string(c),
                                0});
  return submission;
}

StudySubmission one_case_study(double wall_time) { return cases_study(wall_time, 1, 1); }

SchedulerOptions script_options(const ScratchDirectory& scratch, const std::filesystem::path& worker) {
  std::filesystem::permissions(worker, std::filesystem::perms::owner_all);
  SchedulerOptions options;
  options.launcher = {"direct", 1, {}, worker};
  options.data_directory = scratch.path() / "data";
  return options;
}

template <typename Condition>
bool within(std::chrono::seconds limit, Condition condition) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!condition() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(50ms);
  return condition();
}

}  // namespace

TEST_CASE("A case killed at its hard limit is reported with the time it had really run", "[scheduler]") {
  ScratchDirectory scratch("hard-limit");
  const auto worker = scratch.write("stuck-worker.sh", kStuckWorker);
  std::filesystem::permissions(worker, std::filesystem::perms::owner_all);
  Store store(scratch.path() / "store.sqlite");
  const auto study = store.submit_study(one_case_study(0.2)).study_id;

  SchedulerOptions options;
  options.launcher = {"direct", 1, {}, worker};
  options.data_directory = scratch.path() / "data";
  options.hard_limit_factor = 1.5;
  options.hard_limit_margin = 300ms;
  Scheduler scheduler(store, options);
  scheduler.start();
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  while (store.progress(study)->by_status.at("failed") == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(50ms);
  scheduler.stop();

  const auto failed = store.cases(study, CaseStatus::failed, {10, 0});
  REQUIRE(failed.items.size() == 1);
  const auto detail = *store.case_detail(failed.items[0].id);
  REQUIRE(detail.attempts.size() == 1);
  const auto& attempt = detail.attempts[0];
  const double ran = *attempt.ended_at - attempt.started_at;
  std::smatch stated;
  const std::string error = attempt.error.value_or("");
  INFO(error);
  REQUIRE(std::regex_search(error, stated, std::regex("still running ([0-9.]+) s after its start")));
  const double seconds = std::stod(stated[1]);
  // Killed no earlier than 0.2 s x 1.5 + 0.3 s, and the message says how long it had run.
  CHECK(seconds >= 0.6);
  CHECK(seconds == Approx(ran).margin(0.2));
}

TEST_CASE("A worker job that goes silent is killed after the silence limit and its case is not left running",
          "[scheduler]") {
  // As srun was seen to do after Slurm ended its job for a node failure: alive, saying nothing.
  ScratchDirectory scratch("silent-job");
  Store store(scratch.path() / "store.sqlite");
  const auto study = store.submit_study(cases_study(3600.0, 1, 1)).study_id;
  auto options = script_options(scratch, scratch.write("silent-worker.sh", kStuckWorker));
  options.silence_limit = 500ms;
  Scheduler scheduler(store, options);
  scheduler.start();
  REQUIRE(within(20s, [&] { return store.progress(study)->by_status.at("failed") == 1; }));
  scheduler.stop();

  const auto failed = store.cases(study, CaseStatus::failed, {10, 0});
  const auto detail = *store.case_detail(failed.items.at(0).id);
  REQUIRE(detail.attempts.size() == 1);
  CHECK(detail.attempts[0].outcome == std::optional<std::string>("lost"));
  CHECK_THAT(detail.attempts[0].error.value_or(""), Catch::Contains("sending nothing for the silence limit"));
  CHECK(*detail.attempts[0].ended_at - detail.attempts[0].started_at >= 0.5);
}

TEST_CASE("A rank the job gives up: its case goes back to the queue with a failure, and the job gets fewer cases",
          "[scheduler]") {
  ScratchDirectory scratch("rank-lost");
  Store store(scratch.path() / "store.sqlite");
  const auto study = store.submit_study(cases_study(3600.0, 3, 3)).study_id;
  Scheduler scheduler(store, script_options(scratch, scratch.write("rank-losing-worker.sh", kRankLosingWorker)));
  scheduler.start();
  REQUIRE(within(20s, [&] { return scheduler.status().ranks == 1; }));
  REQUIRE(within(20s, [&] { return store.progress(study)->by_status.at("queued") == 2; }));
  std::this_thread::sleep_for(300ms);  // time enough to hand out a case too many, if it would
  const auto status = scheduler.status();
  scheduler.stop();

  CHECK(status.in_flight == 1);                               // the second case, still with the job's one live rank
  CHECK(store.progress(study)->by_status.at("queued") == 3);  // stopping requeued it
  int lost = 0;
  for (const auto& item : store.cases(study, CaseStatus::queued, {10, 0}).items) {
    const auto detail = *store.case_detail(item.id);
    for (const auto& attempt : detail.attempts) {
      if (attempt.outcome != std::optional<std::string>("lost")) continue;
      ++lost;
      CHECK(attempt.error == std::optional<std::string>("rank 1 went silent"));
    }
  }
  CHECK(lost == 1);
}

}  // namespace aerobreak::testing
