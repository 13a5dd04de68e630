#include "orchestrator/worker/rank_worker.hpp"

#include "orchestrator/worker/case_answer.hpp"
#include "orchestrator/worker/mpi_text.hpp"
#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

void run_rank_worker(int rank) {
  while (true) {
    const TextMessage message = wait_for_text(0);
    if (message.tag == kTagStop) return;
    // Rank 0 wrote this assignment itself: a failure to read it back is a bug, not a bad case.
    const CaseAssignment assignment = assignment_from_json(nlohmann::ordered_json::parse(message.text));
    send_text(0, kTagAnswer, serialize_message(answer_assignment(assignment, rank)));
  }
}

}  // namespace aerobreak
