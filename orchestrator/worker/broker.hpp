#pragma once
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "orchestrator/worker/line_reader.hpp"
#include "orchestrator/worker/local_runner.hpp"
#include "orchestrator/worker/mpi_session.hpp"
#include "orchestrator/worker/mpi_text.hpp"
#include "orchestrator/worker/protocol_output.hpp"
#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

// Rank 0's main thread (docs/WORKER_PROTOCOL.md): reads the orchestrator's lines from stdin,
// queues the cases, hands each to the next idle rank (its own LocalRunner included) as soon as
// one is free, so that cheap cases never wait behind a costly one, and forwards every answer to
// stdout. Each rank runs at most one case at a time. It tells the orchestrator every
// kHeartbeatInterval that the job is alive, and gives up on a busy rank that has said nothing for
// the silence limit (stopped, or its node lost or cut off): the rank gets no more cases and its case
// is answered as failed, kind "lost", so that it runs elsewhere instead of holding the study.
class Broker {
 public:
  Broker(const MpiSession& mpi, ProtocolOutput& out, std::vector<std::string> hosts,
         std::chrono::milliseconds silence_limit);

  // Runs until a stop message's cases are all answered, then releases the worker ranks. Stdin
  // ending without a stop aborts the whole job (the results could not be delivered any more), and
  // so does a stop after a rank was lost (MPI_Finalize would wait for it).
  void run();

 private:
  using Clock = std::chrono::steady_clock;
  // What rank 0 knows of one rank.
  struct RankSlot {
    bool busy = false;
    bool lost = false;
    Clock::time_point handed;  // when its case was handed over
    Clock::time_point heard;   // its last message, or the hand-over
    std::int64_t case_id = 0;
    int attempt = 0;
    std::unique_ptr<PendingSend> handover;  // its case on the way to it (worker ranks)
  };

  void serve();
  void read_orchestrator();
  void handle_line(const std::string& line);
  void collect_answers();
  void dispatch();
  void give_up_silent_ranks();
  void say_alive();
  int idle_rank() const;
  bool any_busy() const;
  int lost_ranks() const;

  const MpiSession& mpi_;
  ProtocolOutput& out_;
  std::vector<std::string> hosts_;
  std::chrono::milliseconds silence_limit_;
  LineReader input_;
  std::deque<CaseAssignment> queue_;
  std::vector<RankSlot> ranks_;
  bool stopping_ = false;
  Clock::time_point last_heartbeat_;
  LocalRunner local_;
};

}  // namespace aerobreak
