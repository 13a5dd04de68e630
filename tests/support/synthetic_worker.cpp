// aerobreak_synthetic_worker: a test double of the engine for the adaptive search (docs/ADAPTIVE.md).
// It speaks the worker protocol (docs/WORKER_PROTOCOL.md) on stdin and stdout like `aerobreak
// worker`, so that cases go through the real scheduler and store, but answers each case from the
// seeded synthetic law (synthetic_law.hpp) instead of simulating it: the outcome is a function of
// the case's impact speed, gamma/k_n and seeds alone. Started as `PROGRAM worker` by `aerobreak
// serve --launcher direct --ranks 1 --worker-program PROGRAM`. Environment:
//   AEROBREAK_SYNTHETIC_RANKS  cases it holds at once (the ranks it announces; default 4)
//   AEROBREAK_SYNTHETIC_DELAY  seconds each case takes (default 0)
//   AEROBREAK_SYNTHETIC_DATA   a directory: each result then comes with a small data file written
//                              there, with its size and SHA-256, as the engine's HDF5 files do
//   AEROBREAK_SYNTHETIC_RESULT a result document (a file) each result is a copy of, with the drawn
//                              outcome class: results of a real case's size (the scale benchmark)
//   AEROBREAK_SYNTHETIC_UNDETERMINED  the share of cases that end undetermined (default 0), drawn
//                              from the seeds apart from the outcome, as impacts that hit their time limit
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <variant>

#include "orchestrator/study/sha256.hpp"
#include "orchestrator/worker/worker_protocol.hpp"
#include "tests/support/synthetic_law.hpp"

namespace {

using namespace aerobreak;
using Clock = std::chrono::steady_clock;

struct Pending {
  CaseAssignment assignment;
  Clock::time_point due;
};

double environment_number(const char* name, double fallback) {
  const char* text = std::getenv(name);
  return text ? std::atof(text) : fallback;
}

void send(const nlohmann::ordered_json& message) {
  const std::string line = protocol_line(message);
  if (::write(STDOUT_FILENO, line.data(), line.size()) < 0) std::exit(1);
}

// The document results start from: AEROBREAK_SYNTHETIC_RESULT's, or a minimal one.
nlohmann::ordered_json result_template() {
  const char* file = std::getenv("AEROBREAK_SYNTHETIC_RESULT");
  if (!file) return {{"outcome", {{"class", ""}}}, {"synthetic", true}};
  std::ifstream in(file);
  return nlohmann::ordered_json::parse(in);
}

void answer(const CaseAssignment& a) {
  const auto& d = a.document;
  const double speed = d.at("impact").at("speed").get<double>();
  const double gamma = d.at("material").value("gamma_over_kn", 0.001);
  const auto cluster_seed = d.at("cluster").at("generator").value("seed", std::uint64_t{0});
  const auto orientation_seed = d.at("impact").value("orientation_seed", std::uint64_t{0});
  const bool undetermined = testing::uniform_from_seeds(orientation_seed, cluster_seed) <
                            environment_number("AEROBREAK_SYNTHETIC_UNDETERMINED", 0.0);
  const std::string outcome =
      undetermined
          ? "undetermined"
          : testing::SyntheticLaw{}.outcome(speed, gamma, testing::uniform_from_seeds(cluster_seed, orientation_seed));
  static const nlohmann::ordered_json kTemplate = result_template();
  nlohmann::ordered_json result = kTemplate;
  result["outcome"]["class"] = outcome;
  const char* data_directory = std::getenv("AEROBREAK_SYNTHETIC_DATA");
  if (!data_directory) {
    send(result_message(a.case_id, a.attempt, 0, 0.0, result, ""));
    return;
  }
  const auto file = std::filesystem::path(data_directory) /
                    ("case-" + std::to_string(a.case_id) + "-" + std::to_string(a.attempt) + ".txt");
  std::ofstream(file) << result.dump() << "\n";
  send(result_message(a.case_id, a.attempt, 0, 0.0, result, file.string(), std::filesystem::file_size(file),
                      sha256_hex_of_file(file)));
}

// Reads whole lines from stdin without blocking past `timeout_ms`; false at end of input.
bool read_lines(std::string& buffer, std::deque<std::string>& lines, int timeout_ms) {
  pollfd input{STDIN_FILENO, POLLIN, 0};
  if (::poll(&input, 1, timeout_ms) <= 0) return true;
  char chunk[65536];
  const ssize_t n = ::read(STDIN_FILENO, chunk, sizeof chunk);
  if (n <= 0) return false;
  buffer.append(chunk, static_cast<std::size_t>(n));
  for (auto end = buffer.find('\n'); end != std::string::npos; end = buffer.find('\n')) {
    lines.push_back(buffer.substr(0, end));
    buffer.erase(0, end + 1);
  }
  return true;
}

}  // namespace

int main() {
  const int ranks = static_cast<int>(environment_number("AEROBREAK_SYNTHETIC_RANKS", 4));
  const auto delay = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(environment_number("AEROBREAK_SYNTHETIC_DELAY", 0.0)));
  send(ready_message(ranks, std::vector<std::string>(static_cast<std::size_t>(ranks), "synthetic"), ::getpid(),
                     "synthetic"));
  std::deque<Pending> pending;
  std::deque<std::string> lines;
  std::string buffer;
  bool stopping = false;
  auto last_heartbeat = Clock::now();
  while (!stopping || !pending.empty()) {
    if (Clock::now() - last_heartbeat >= kHeartbeatInterval) {  // as rank 0 of a real job does
      send(heartbeat_message());
      last_heartbeat = Clock::now();
    }
    while (!pending.empty() && (stopping || pending.front().due <= Clock::now())) {
      answer(pending.front().assignment);
      pending.pop_front();
    }
    if (stopping) continue;
    if (!read_lines(buffer, lines, pending.empty() ? 1000 : 10)) return 1;  // the orchestrator is gone
    for (; !lines.empty(); lines.pop_front()) {
      if (lines.front().empty()) continue;
      OrchestratorMessage message;
      try {
        message = decode_orchestrator_line(lines.front());
      } catch (const ProtocolError& error) {
        send(protocol_error_message(error.what()));
        continue;
      }
      if (const auto* m = std::get_if<MalformedAssignment>(&message)) {
        send(failed_message(m->case_id, m->attempt, 0, 0.0, FailureKind::invalid, m->error));
      } else if (const auto* a = std::get_if<CaseAssignment>(&message)) {
        send(started_message(a->case_id, a->attempt, 0, "synthetic"));
        pending.push_back({*a, Clock::now() + delay});
      } else if (std::holds_alternative<StopRequest>(message)) {
        stopping = true;
      }
    }
  }
  return 0;
}
