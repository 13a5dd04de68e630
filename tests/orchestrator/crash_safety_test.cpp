// Nothing lost on a crash: the orchestrator killed with SIGKILL and started again, a worker job
// killed under it, a case that keeps failing, a case that overruns its wall time.
#include <map>
#include <set>

#include "tests/orchestrator/service_process.hpp"

namespace aerobreak::testing {
namespace {

std::string study_path(std::int64_t study, const std::string& tail = {}) {
  return "/api/studies/" + std::to_string(study) + tail;
}

Json all_cases(const ServiceProcess& service, std::int64_t study) {
  return service.get(study_path(study, "/cases?limit=1000")).at("items");
}

}  // namespace

TEST_CASE("SIGKILL of the orchestrator mid-study: the restarted one finishes it, no finished result lost",
          "[service][crash]") {
  ScratchDirectory scratch("sigkill");
  std::map<std::int64_t, double> committed_before;
  std::int64_t study = 0;
  pid_t job_pid = 0;
  {
    ServiceProcess service(scratch.path());
    study = submit(service, slow_study("sigkill", 10)).at("id").get<std::int64_t>();
    REQUIRE(eventually(
        [&] { return service.get(study_path(study, "/progress")).at("counts").at("done").get<int>() >= 2; }, 60s));
    const auto health = service.get("/api/health");
    REQUIRE(health.at("scheduler").at("job").is_object());
    job_pid = health.at("scheduler").at("job").at("pid").get<pid_t>();
    CHECK(service.kill(SIGKILL) == 128 + SIGKILL);
  }
  // The worker job notices its orchestrator is gone (stdin closed) and ends by itself.
  CHECK(eventually([&] { return !process_alive(job_pid); }, 20s));

  ServiceProcess restarted(scratch.path());
  const auto results_before = restarted.get(study_path(study, "/results?limit=1000"));
  for (const auto& result : results_before.at("items"))
    committed_before[result.at("case").get<std::int64_t>()] = result.at("committed_at").get<double>();
  REQUIRE(committed_before.size() >= 2);
  REQUIRE(committed_before.size() < 10);
  REQUIRE(eventually([&] { return study_complete(restarted, study); }, 120s));

  const auto results = restarted.get(study_path(study, "/results?limit=1000"));
  CHECK(results.at("total") == 10);
  std::set<std::int64_t> cases;
  for (const auto& result : results.at("items")) {
    const auto id = result.at("case").get<std::int64_t>();
    CHECK(cases.insert(id).second);
    if (committed_before.count(id)) CHECK(result.at("committed_at").get<double>() == committed_before.at(id));
  }
  std::size_t interrupted = 0;
  for (const auto& record : all_cases(restarted, study)) {
    CHECK(record.at("status") == "done");
    CHECK(record.at("failures") == 0);
    const auto detail = restarted.get("/api/cases/" + std::to_string(record.at("id").get<std::int64_t>()));
    for (const auto& attempt : detail.at("attempt_history")) interrupted += attempt.at("outcome") == "interrupted";
  }
  CHECK(interrupted >= 1);
}

TEST_CASE("A killed worker job: its in-flight cases are queued again and the study finishes", "[service][crash]") {
  ScratchDirectory scratch("killed-worker");
  ServiceProcess service(scratch.path());
  const auto study = submit(service, slow_study("killed worker", 6)).at("id").get<std::int64_t>();
  pid_t job_pid = 0;
  REQUIRE(eventually(
      [&] {
        const auto job = service.get("/api/health").at("scheduler").at("job");
        if (!job.is_object() || job.at("in_flight").get<int>() == 0) return false;
        job_pid = job.at("pid").get<pid_t>();
        return true;
      },
      30s));
  ::kill(job_pid, SIGKILL);
  REQUIRE(eventually([&] { return study_complete(service, study); }, 120s));

  std::size_t lost = 0;
  for (const auto& record : all_cases(service, study)) {
    const auto detail = service.get("/api/cases/" + std::to_string(record.at("id").get<std::int64_t>()));
    INFO(detail.at("attempt_history").dump());
    CHECK(record.at("status") == "done");
    for (const auto& attempt : detail.at("attempt_history")) lost += attempt.at("outcome") == "lost";
  }
  CHECK(lost >= 1);
  CHECK(service.get(study_path(study, "/results")).at("total") == 6);
  CHECK(service.get("/api/health").at("scheduler").at("jobs_started").get<int>() >= 2);
}

TEST_CASE("A case that keeps overrunning its wall time is failed after max_attempts while the others finish",
          "[service][crash]") {
  ScratchDirectory scratch("poison");
  ServiceProcess service(scratch.path());
  // 16 primaries settle in ~0.1 s; 1024 primaries over a long time limit need far more than 1 s.
  auto study = small_study("poison", {0.01}, 1);
  study["base"]["cluster"]["generator"].erase("primaries");
  study["axes"]["primaries"] = {{"values", {16, 1024}}};
  study["base"]["run"]["time_limit"] = 1e6;
  study["execution"] = {{"max_attempts", 2}, {"case_wall_time", 1.0}};
  const auto id = submit(service, study).at("id").get<std::int64_t>();
  REQUIRE(eventually([&] { return study_complete(service, id); }, 90s));

  const auto progress = service.get(study_path(id, "/progress"));
  CHECK(progress.at("counts").at("done") == 1);
  CHECK(progress.at("counts").at("failed") == 1);
  const auto failed = service.get(study_path(id, "/cases?status=failed")).at("items");
  REQUIRE(failed.size() == 1);
  CHECK(failed[0].at("grid_point").at("primaries") == 1024);
  CHECK(failed[0].at("attempts") == 2);
  CHECK_THAT(failed[0].at("error").get<std::string>(), Catch::Contains("wall"));
  const auto detail = service.get("/api/cases/" + std::to_string(failed[0].at("id").get<std::int64_t>()));
  REQUIRE(detail.at("attempt_history").size() == 2);
  for (const auto& attempt : detail.at("attempt_history")) {
    CHECK(attempt.at("outcome") == "wall_time");
    // Stopped by the worker itself near the limit, not by the orchestrator's hard limit.
    CHECK(attempt.at("ended_at").get<double>() - attempt.at("started_at").get<double>() < 10.0);
  }
}

}  // namespace aerobreak::testing
