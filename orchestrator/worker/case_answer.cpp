#include "orchestrator/worker/case_answer.hpp"

#include <chrono>
#include <exception>

#include "engine/impact/impact_case.hpp"
#include "orchestrator/worker/case_data_file.hpp"
#include "orchestrator/worker/case_runner.hpp"

namespace aerobreak {

nlohmann::ordered_json answer_assignment(const CaseAssignment& a, int rank) {
  const auto start = std::chrono::steady_clock::now();
  const auto failed = [&](FailureKind kind, const std::string& error) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return failed_message(a.case_id, a.attempt, rank, seconds, kind, error);
  };
  try {
    CaseRunOutcome outcome = run_case(a.document, a.wall_time, a.data_file);
    return result_message(a.case_id, a.attempt, rank, outcome.seconds, std::move(outcome.result), outcome.data_file,
                          outcome.data_file_size, outcome.data_file_sha256);
  } catch (const CaseError& e) {
    return failed(FailureKind::invalid, e.what());
  } catch (const WallTimeExceeded& e) {
    return failed(FailureKind::wall_time, e.what());
  } catch (const DataFileError& e) {
    return failed(FailureKind::storage, e.what());
  } catch (const std::exception& e) {
    return failed(FailureKind::error, e.what());
  } catch (...) {
    return failed(FailureKind::error, "unknown exception");
  }
}

nlohmann::ordered_json answer_malformed(const MalformedAssignment& m, int rank) {
  return failed_message(m.case_id, m.attempt, rank, 0.0, FailureKind::invalid, m.error);
}

}  // namespace aerobreak
