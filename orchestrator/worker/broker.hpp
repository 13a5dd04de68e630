#pragma once
#include <deque>
#include <string>
#include <vector>

#include "orchestrator/worker/line_reader.hpp"
#include "orchestrator/worker/local_runner.hpp"
#include "orchestrator/worker/mpi_session.hpp"
#include "orchestrator/worker/protocol_output.hpp"
#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

// Rank 0's main thread (docs/WORKER_PROTOCOL.md): reads the orchestrator's lines from stdin,
// queues the cases, hands each to the next idle rank (its own LocalRunner included) as soon as
// one is free, so that cheap cases never wait behind a costly one, and forwards every answer to
// stdout. Each rank runs at most one case at a time.
class Broker {
 public:
  Broker(const MpiSession& mpi, ProtocolOutput& out, std::vector<std::string> hosts);

  // Runs until a stop message's cases are all answered, then releases the worker ranks. Stdin
  // ending without a stop aborts the whole job (the results could not be delivered any more).
  void run();

 private:
  void serve();
  void read_orchestrator();
  void handle_line(const std::string& line);
  void collect_answers();
  void dispatch();
  int idle_rank() const;
  bool any_busy() const;

  const MpiSession& mpi_;
  ProtocolOutput& out_;
  std::vector<std::string> hosts_;
  LineReader input_;
  std::deque<CaseAssignment> queue_;
  std::vector<bool> busy_;  // per rank
  bool stopping_ = false;
  LocalRunner local_;
};

}  // namespace aerobreak
