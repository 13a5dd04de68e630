// The scheduler in this process over a real store, with a worker job that is a shell script
// speaking the line protocol (docs/WORKER_PROTOCOL.md) and then never answering its case.
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

StudySubmission one_case_study(double wall_time) {
  StudySubmission submission;
  submission.hash = "stuck-study";
  submission.name = "stuck";
  submission.document = nlohmann::ordered_json::object();
  submission.max_attempts = 1;
  submission.case_wall_time = wall_time;
  submission.cases.push_back({"stuck-case", nlohmann::ordered_json::object(), {{"impact_speed", 0.01}}, "k", 0});
  return submission;
}

}  // namespace

TEST_CASE("A case killed at its hard limit is reported with the time it had really run",
          "[scheduler]") {
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

}  // namespace aerobreak::testing
