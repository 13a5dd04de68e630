// How many worker ranks one orchestrator and one SQLite store can feed (docs/ORCHESTRATOR.md,
// "Scale"); prints figures, asserts nothing.
//   scheduler_scale_bench SYNTHETIC_WORKER [DIRECTORY] [DELAY]
// The real scheduler, in this process, over a real store file in DIRECTORY (default: the system's
// temporary folder; put it on the file system the store will live on), feeds the synthetic worker
// (tests/support/synthetic_worker.cpp: one process that announces K ranks and answers each case
// after a set delay) with the cases of a real study. Each result is a copy of a real case's result
// document, so that a commit writes what the engine's would. For K = 1, 16, 64 and 256 ranks:
//   1. saturation: every case answered at once; cases committed per second, and the orchestrator's
//      CPU time per case (this process: scheduler thread and job reader; the worker is another);
//   2. cases of DELAY seconds (default 1): the wall time against the ideal cases x DELAY / K, and
//      the rank time lost per case waiting for the orchestrator: K x wall / cases - DELAY.
#include <sys/resource.h>
#include <sys/statfs.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "orchestrator/scheduler/scheduler.hpp"
#include "orchestrator/app/study_submission.hpp"
#include "orchestrator/worker/case_runner.hpp"

namespace aerobreak {
namespace {

using Clock = std::chrono::steady_clock;

// The default study's kind of case (a relaxed ballistic cluster of 32 primaries, reduced units),
// swept over speeds and replicates to as many cases as asked.
nlohmann::ordered_json study_document(int cases, const std::string& name) {
  const int speeds = 40;
  return {{"name", name},
          {"base",
           {{"cluster", {{"generator", {{"method", "ballistic"}, {"primaries", 32}}}}},
            {"material", {{"gamma_over_kn", 0.001}}},
            {"model", {{"damping", {{"law", "viscoelastic"}, {"dissipative_time", 0.05}}}}},
            {"run", {{"time_limit", 20000}}}}},
          {"axes", {{"impact_speed", {{"log", {{"from", 0.003}, {"to", 0.3}, {"count", speeds}}}}}}},
          {"replicates", {{"count", std::max(1, (cases + speeds - 1) / speeds)}, {"seed", 2026}}}};
}

double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

struct Measurement {
  std::size_t cases = 0;
  double wall = 0.0;  // s, from the scheduler's start to the last commit
  double cpu = 0.0;   // s of this process
};

// Runs a fresh store's study of `cases` cases on a job of `ranks` synthetic ranks taking `delay` s
// per case.
Measurement run_study(const std::filesystem::path& directory, const std::filesystem::path& worker, int ranks,
                      double delay, int cases) {
  const auto file = directory / ("scale-" + std::to_string(ranks) + "-" + std::to_string(delay) + ".sqlite");
  for (const char* suffix : {"", "-wal", "-shm", ".lock"}) std::filesystem::remove(file.string() + suffix);
  Store store(file);
  const Study study = parse_study(study_document(cases, "scale"));
  const auto study_id = store.submit_study(make_submission(study)).study_id;
  ::setenv("AEROBREAK_SYNTHETIC_RANKS", std::to_string(ranks).c_str(), 1);
  ::setenv("AEROBREAK_SYNTHETIC_DELAY", std::to_string(delay).c_str(), 1);

  SchedulerOptions options;
  options.launcher = {"direct", 1, {}, worker};
  options.data_directory = directory / "scale.data";
  Measurement m;
  m.cases = study.cases.size();
  const double cpu_before = cpu_seconds();
  const auto start = Clock::now();
  Scheduler scheduler(store, options);
  scheduler.start();
  while (static_cast<std::size_t>(store.progress(study_id)->by_status.at("done")) < m.cases)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  m.wall = std::chrono::duration<double>(Clock::now() - start).count();
  m.cpu = cpu_seconds() - cpu_before;
  scheduler.stop();
  return m;
}

// A real case's result document, written to a file for the synthetic worker to copy.
std::filesystem::path real_result_file(const std::filesystem::path& directory) {
  const Study study = parse_study(study_document(1, "template"));
  const CaseRunOutcome outcome = run_case(study.cases.front().document, 0.0, {});
  const auto file = directory / "result-template.json";
  std::ofstream(file) << outcome.result.dump();
  return file;
}

std::string file_system_of(const std::filesystem::path& directory) {
  struct statfs info {};
  if (statfs(directory.c_str(), &info) != 0) return "?";
  switch (info.f_type) {
    case 0xEF53:
      return "ext4";
    case 0x01021994:
      return "tmpfs";
    case 0x794c7630:
      return "overlayfs";
    case 0x58465342:
      return "xfs";
    case 0x9123683E:
      return "btrfs";
    default: {
      char hex[32];
      std::snprintf(hex, sizeof hex, "type 0x%lx", static_cast<unsigned long>(info.f_type));
      return hex;
    }
  }
}

}  // namespace
}  // namespace aerobreak

int main(int argc, char** argv) {
  using namespace aerobreak;
  if (argc < 2) {
    std::fprintf(stderr, "usage: scheduler_scale_bench SYNTHETIC_WORKER [DIRECTORY] [DELAY]\n");
    return 2;
  }
  const std::filesystem::path worker = std::filesystem::absolute(argv[1]);
  const auto directory = std::filesystem::absolute(argc > 2 ? argv[2] : std::filesystem::temp_directory_path()) /
                         ("aerobreak-scale-" + std::to_string(::getpid()));
  const double delay = argc > 3 ? std::atof(argv[3]) : 1.0;
  std::filesystem::create_directories(directory);
  const auto result = real_result_file(directory);
  ::setenv("AEROBREAK_SYNTHETIC_RESULT", result.c_str(), 1);
  std::printf("store in %s (%s); result documents of %ju bytes (a real case's); synthetic cases of %g s\n",
              directory.c_str(), file_system_of(directory).c_str(), std::filesystem::file_size(result), delay);
  std::printf("%6s | %26s | cases of %g s\n", "", "saturation (cases at once)", delay);
  std::printf("%6s | %6s %9s %9s | %6s %7s %7s %12s %10s\n", "ranks", "cases", "commits/s", "CPU ms", "cases", "wall s",
              "ideal s", "lost ms/case", "efficiency");
  for (const int ranks : {1, 16, 64, 256}) {
    const Measurement saturated = run_study(directory, worker, ranks, 0.0, 3000);
    const Measurement timed = run_study(directory, worker, ranks, delay, std::max(20, 8 * ranks));
    const double ideal = static_cast<double>(timed.cases) * delay / ranks;
    std::printf("%6d | %6zu %9.0f %9.2f | %6zu %7.1f %7.1f %12.1f %10.2f\n", ranks, saturated.cases,
                static_cast<double>(saturated.cases) / saturated.wall,
                1000.0 * saturated.cpu / static_cast<double>(saturated.cases), timed.cases, timed.wall, ideal,
                1000.0 * (ranks * timed.wall / static_cast<double>(timed.cases) - delay), ideal / timed.wall);
    std::fflush(stdout);
  }
  std::filesystem::remove_all(directory);
  return 0;
}
