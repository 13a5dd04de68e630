#include "orchestrator/worker/case_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_result.hpp"
#include "engine/impact/impact_run.hpp"
#include "orchestrator/study/sha256.hpp"
#include "orchestrator/worker/case_data_file.hpp"

namespace aerobreak {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The deadline of one case, checked wherever the engine hands control back.
class WallTimeLimit {
 public:
  WallTimeLimit(double wall_time, Clock::time_point start) : wall_time_(wall_time), start_(start) {}

  bool limited() const { return wall_time_ > 0.0; }

  // How often the impact stage reports progress, so that the deadline is checked often enough:
  // a twentieth of the limit, at most a second, and not so often that the progress sampling (a
  // fragment analysis each time) costs noticeable time.
  double check_interval() const { return std::clamp(wall_time_ / 20.0, 0.01, 1.0); }

  void check(const char* stage) const {
    if (!limited()) return;
    const double elapsed = seconds_since(start_);
    if (elapsed <= wall_time_) return;
    char message[160];
    std::snprintf(message, sizeof message, "the case ran past its wall time of %.6g s (stopped after %.3f s, %s)",
                  wall_time_, elapsed, stage);
    throw WallTimeExceeded(message);
  }

 private:
  double wall_time_;
  Clock::time_point start_;
};

}  // namespace

CaseRunOutcome run_case(const nlohmann::ordered_json& document, double wall_time,
                        const std::filesystem::path& data_file) {
  const auto start = Clock::now();
  const WallTimeLimit limit(wall_time, start);
  const ImpactCase impact_case = parse_impact_case(document);

  std::optional<CaseDataFile> bulk;
  if (!data_file.empty()) bulk.emplace(data_file);

  ImpactRunOptions options;
  options.log = [&limit](const std::string&) { limit.check("while preparing the cluster"); };
  if (bulk) options.snapshot = [&bulk](const Simulation& simulation) { bulk->record(simulation); };
  if (limit.limited()) {
    options.progress = [&limit](const ImpactProgress&) { limit.check("during the impact"); };
    options.progress_seconds = limit.check_interval();
  }
  const ImpactResult result = run_impact(impact_case, options);

  CaseRunOutcome outcome;
  outcome.result = to_json(result);
  if (bulk) {
    bulk->commit();
    outcome.data_file = bulk->path().string();
    try {
      outcome.data_file_size = std::filesystem::file_size(bulk->path());
      outcome.data_file_sha256 = sha256_hex_of_file(bulk->path());
    } catch (const std::exception& error) {
      throw DataFileError("cannot read back the data file " + outcome.data_file + ": " + error.what());
    }
  }
  outcome.seconds = seconds_since(start);
  return outcome;
}

}  // namespace aerobreak
