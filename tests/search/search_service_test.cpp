// Whole adaptive searches through `aerobreak serve`: the real scheduler and store, worker jobs of
// the engine's test double (tests/support/synthetic_worker.cpp, the seeded synthetic law), the
// REST API. Every round stored must be the round plan_round decides from the results of the
// rounds before it (whatever order they arrived in), and a search SIGKILLed mid-way must go on
// after a restart as the same search, nothing rerun.
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

#include "orchestrator/search/boundary_search.hpp"
#include "orchestrator/study/study.hpp"
#include "tests/orchestrator/service_process.hpp"
#include "tests/support/synthetic_law.hpp"

namespace aerobreak::testing {
namespace {

Json search_study(const std::string& name) {
  return {{"name", name},
          {"base",
           {{"cluster", {{"generator", {{"method", "ballistic"}, {"primaries", 16}}}}},
            {"model", {{"damping", {{"law", "viscoelastic"}, {"dissipative_time", 0.05}}}}},
            {"run", {{"time_limit", 20000.0}}}}},
          {"axes", {{"gamma_over_kn", {{"values", {0.001, 0.004}}}}}},
          {"search",
           {{"axis", "impact_speed"},
            {"range", {{"from", 0.005}, {"to", 0.3}}},
            {"relative_width", 0.5},
            {"budget", 120},
            {"batch", 8},
            {"initial", 8}}},
          {"replicates", {{"seed", 7}}}};
}

// The service with worker jobs of the engine's test double: one process holding 4 cases at once,
// each answered after `delay` seconds.
std::unique_ptr<ServiceProcess> synthetic_service(const std::filesystem::path& directory, const char* delay) {
  ::setenv("AEROBREAK_SYNTHETIC_DELAY", delay, 1);
  ::setenv("AEROBREAK_SYNTHETIC_RANKS", "4", 1);
  return std::make_unique<ServiceProcess>(
      directory,
      std::vector<std::string>{"--launcher", "direct", "--ranks", "1", "--worker-program", AEROBREAK_SYNTHETIC_WORKER});
}

Json search_of(const ServiceProcess& service, std::int64_t study) {
  return service.get("/api/studies/" + std::to_string(study) + "/search");
}

Json all_cases(const ServiceProcess& service, std::int64_t study) {
  return service.get("/api/studies/" + std::to_string(study) + "/cases?limit=1000").at("items");
}

// The cases of one group, by replicate (= placement order in the group).
std::map<int, Json> group_cases(const Json& cases, const Json& group, const std::string& axis) {
  std::map<int, Json> out;
  for (const auto& c : cases) {
    Json point = c.at("grid_point");
    point.erase(axis);
    if (point == group) out[c.at("replicate").get<int>()] = c;
  }
  return out;
}

// Every stored round of every group is the round plan_round decides from the finished cases of
// the rounds before it, with the same seed; the group's end is the decision on all its results.
void check_rounds_replay(const Study& study, const Json& search, const Json& cases) {
  const auto& spec = *study.search;
  for (const auto& group : search.at("groups")) {
    const auto position = group.at("position").get<std::int64_t>();
    const auto by_replicate = group_cases(cases, group.at("group"), spec.axis);
    REQUIRE(static_cast<int>(by_replicate.size()) == group.at("cases").get<int>());
    std::vector<SearchObservation> observations;
    int placed = 0;
    for (const auto& round : group.at("history")) {
      const int r = round.at("round").get<int>();
      INFO("group " << position << " round " << r);
      if (r > 0) {
        const auto plan = plan_round(spec, observations, round_context(study.seed, position, r, placed));
        CHECK(plan.values == round.at("values").get<std::vector<double>>());
      }
      for (const auto& value : round.at("values")) {
        const auto& c = by_replicate.at(placed++);
        CHECK(c.at("grid_point").at(spec.axis).get<double>() == value.get<double>());
        if (c.at("outcome").is_string())
          observations.push_back({value.get<double>(), c.at("outcome").get<std::string>(), r});
      }
    }
    const auto last =
        plan_round(spec, observations, round_context(study.seed, position, group.at("rounds").get<int>(), placed));
    CHECK(to_string(last.state) == group.at("state").get<std::string>());
    CHECK(last.values.empty());
  }
}

}  // namespace

TEST_CASE("An adaptive search through the scheduler and store finds each group's v50 in rounds", "[search][service]") {
  ScratchDirectory scratch("adaptive-search");
  auto service = synthetic_service(scratch.path(), "0");
  const auto id = submit(*service, search_study("adaptive")).at("id").get<std::int64_t>();
  REQUIRE(eventually([&] { return study_complete(*service, id); }, 120s));

  const auto search = search_of(*service, id);
  const auto cases = all_cases(*service, id);
  const Study study = parse_study(search_study("adaptive"));
  check_rounds_replay(study, search, cases);
  const SyntheticLaw law;
  REQUIRE(search.at("groups").size() == 2);
  for (const auto& group : search.at("groups")) {
    INFO(group.dump());
    CHECK(group.at("state") == "converged");
    CHECK(group.at("rounds").get<int>() >= 2);
    CHECK(group.at("cases").get<int>() <= 120);
    const auto& v50 = group.at("estimates").at(0);
    CHECK(v50.at("response") == "break-up");
    CHECK(v50.at("narrow_enough") == true);
    CHECK(v50.at("found") == true);
    // One interval misses the truth one time in twenty (the coverage test counts how often); the
    // estimate itself lies within a quarter of the truth.
    const double truth = law.crossing("break-up", 0.5, group.at("group").at("gamma_over_kn").get<double>());
    CHECK(std::abs(v50.at("estimate").get<double>() / truth - 1.0) < 0.25);
    CHECK((v50.at("upper").get<double>() - v50.at("lower").get<double>()) / v50.at("estimate").get<double>() <= 0.5);
  }
  // Progress shows each group's estimate; every case ran once.
  const auto progress = service->get("/api/studies/" + std::to_string(id) + "/progress");
  CHECK(progress.at("search").size() == 2);
  CHECK(progress.at("search").at(0).at("estimates").at(0).at("estimate").is_number());
  for (const auto& c : cases) {
    CHECK(c.at("status") == "done");
    CHECK(c.at("attempts") == 1);
  }
}

TEST_CASE("SIGKILL of the orchestrator mid-search: the restarted one goes on with the same search, nothing rerun",
          "[search][service][crash]") {
  ScratchDirectory scratch("adaptive-sigkill");
  std::int64_t id = 0;
  Json rounds_before, results_before;
  {
    auto service = synthetic_service(scratch.path(), "0.1");
    id = submit(*service, search_study("adaptive sigkill")).at("id").get<std::int64_t>();
    const bool mid_search = eventually(
        [&] {
          const auto search = search_of(*service, id);
          for (const auto& group : search.at("groups"))
            if (group.at("rounds").get<int>() >= 3) return true;
          return false;
        },
        60s);
    if (!mid_search) FAIL(service->log() << search_of(*service, id).dump());
    rounds_before = search_of(*service, id).at("groups");
    results_before = service->get("/api/studies/" + std::to_string(id) + "/results?limit=1000").at("items");
    CHECK(service->kill(SIGKILL) == 128 + SIGKILL);
    bool searching = false;
    for (const auto& group : rounds_before) searching = searching || group.at("state") == "searching";
    REQUIRE(searching);  // killed mid-search
  }
  REQUIRE_FALSE(results_before.empty());
  auto restarted = synthetic_service(scratch.path(), "0");
  REQUIRE(eventually([&] { return study_complete(*restarted, id); }, 120s));

  const auto search = search_of(*restarted, id);
  const auto cases = all_cases(*restarted, id);
  check_rounds_replay(parse_study(search_study("adaptive sigkill")), search, cases);
  // The rounds decided before the kill stand as they were.
  for (std::size_t g = 0; g < rounds_before.size(); ++g)
    for (const auto& round : rounds_before[g].at("history")) {
      const auto& now = search.at("groups").at(g).at("history").at(round.at("round").get<std::size_t>());
      CHECK(now.at("values") == round.at("values"));
      CHECK(now.at("decided_at") == round.at("decided_at"));
    }
  // Results committed before the kill are kept, not recomputed; no case failed or ran twice.
  std::map<std::int64_t, double> committed;
  const auto results = restarted->get("/api/studies/" + std::to_string(id) + "/results?limit=1000");
  for (const auto& r : results.at("items"))
    committed[r.at("case").get<std::int64_t>()] = r.at("committed_at").get<double>();
  INFO(committed.size() << " results now, " << results_before.size() << " before the kill");
  for (const auto& r : results_before) {
    const auto found = committed.find(r.at("case").get<std::int64_t>());
    REQUIRE(found != committed.end());
    CHECK(found->second == r.at("committed_at").get<double>());
  }
  std::set<std::int64_t> before;
  for (const auto& r : results_before) before.insert(r.at("case").get<std::int64_t>());
  for (const auto& c : cases) {
    CHECK(c.at("status") == "done");
    CHECK(c.at("failures") == 0);
    if (before.count(c.at("id").get<std::int64_t>())) CHECK(c.at("attempts") == 1);
  }
  for (const auto& group : search.at("groups")) CHECK(group.at("state") != "searching");
}

TEST_CASE("A search study submitted again reports the lost data files of every round, and recomputes them when asked",
          "[search][service]") {
  ScratchDirectory scratch("adaptive-data-files");
  const auto data = scratch.path() / "synthetic-data";
  std::filesystem::create_directories(data);
  ::setenv("AEROBREAK_SYNTHETIC_DATA", data.c_str(), 1);
  auto service = synthetic_service(scratch.path(), "0");
  ::unsetenv("AEROBREAK_SYNTHETIC_DATA");
  const Json document = search_study("adaptive data files");
  const auto id = submit(*service, document).at("id").get<std::int64_t>();
  REQUIRE(eventually([&] { return study_complete(*service, id); }, 120s));
  const auto before = search_of(*service, id).at("groups");

  // The first case of group 0 (round 0) and its last (placed by a later round): both files lost.
  const auto by_replicate = group_cases(all_cases(*service, id), before.at(0).at("group"), "impact_speed");
  REQUIRE(by_replicate.size() > 8);
  const std::vector<std::int64_t> lost{by_replicate.begin()->second.at("id").get<std::int64_t>(),
                                       by_replicate.rbegin()->second.at("id").get<std::int64_t>()};
  for (const auto case_id : lost) {
    const auto detail = service->get("/api/cases/" + std::to_string(case_id));
    REQUIRE(detail.at("data_file_check").at("state") == "ok");
    std::filesystem::remove(detail.at("data_file").get<std::string>());
  }

  // Reported, their results kept; computed again only when asked.
  const auto reported = submit(*service, document, 200);
  CHECK(reported.at("data_files_lost") == 2);
  CHECK(reported.at("recomputed") == 0);
  for (const auto case_id : lost) CHECK(service->get("/api/cases/" + std::to_string(case_id)).at("status") == "done");
  const auto receipt = submit(*service, document, 200, "?recompute_data_files=true");
  CHECK(receipt.at("recomputed") == 2);
  REQUIRE(eventually([&] { return study_complete(*service, id); }, 120s));
  for (const auto case_id : lost) {
    const auto detail = service->get("/api/cases/" + std::to_string(case_id));
    CHECK(detail.at("status") == "done");
    CHECK(detail.at("data_file_check").at("state") == "ok");
    CHECK(detail.at("attempt_history").size() == 2);
  }
  // The search stands as it was: the same rounds, state and estimates.
  const auto after = search_of(*service, id).at("groups");
  REQUIRE(after.size() == before.size());
  for (std::size_t g = 0; g < before.size(); ++g)
    for (const char* field : {"state", "rounds", "cases", "estimates", "history"})
      CHECK(after.at(g).at(field) == before.at(g).at(field));
}

}  // namespace aerobreak::testing
