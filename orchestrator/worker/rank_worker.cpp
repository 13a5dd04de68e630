#include "orchestrator/worker/rank_worker.hpp"

#include <mpi.h>

#include <chrono>
#include <thread>

#include "orchestrator/worker/local_runner.hpp"
#include "orchestrator/worker/mpi_text.hpp"
#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

void run_rank_worker(int rank) {
  using Clock = std::chrono::steady_clock;
  // The case runs on the runner's thread, so that this one stays free to tell rank 0 that the rank
  // is alive: a rank that falls silent (stopped, its node cut off) is then told from a long case.
  LocalRunner runner(rank);
  bool busy = false;
  auto last_said = Clock::now();
  while (true) {
    if (auto message = try_receive_text(0, MPI_ANY_TAG)) {
      if (message->tag == kTagStop) return;
      // Rank 0 wrote this assignment itself: a failure to read it back is a bug, not a bad case.
      runner.start(assignment_from_json(nlohmann::ordered_json::parse(message->text)));
      busy = true;
      last_said = Clock::now();
    }
    if (auto answer = runner.take_answer()) {
      send_text(0, kTagAnswer, *answer);
      busy = false;
    } else if (busy && Clock::now() - last_said >= kHeartbeatInterval) {
      send_text(0, kTagAlive, {});
      last_said = Clock::now();
    }
    std::this_thread::sleep_for(kPollPause);
  }
}

}  // namespace aerobreak
