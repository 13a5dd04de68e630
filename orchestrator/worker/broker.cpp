#include "orchestrator/worker/broker.hpp"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <exception>
#include <thread>
#include <variant>

#include "orchestrator/worker/case_answer.hpp"
#include "orchestrator/worker/mpi_text.hpp"

namespace aerobreak {

Broker::Broker(const MpiSession& mpi, ProtocolOutput& out, std::vector<std::string> hosts)
    : mpi_(mpi),
      out_(out),
      hosts_(std::move(hosts)),
      input_(STDIN_FILENO),
      busy_(static_cast<std::size_t>(mpi.size()), false),
      local_(0) {}

void Broker::run() {
  try {
    serve();
  } catch (const std::exception& e) {
    // Abort from here, while the case thread may still compute: unwinding past local_ would
    // first wait for its case to finish.
    mpi_.abort(e.what());
  }
}

void Broker::serve() {
  while (!(stopping_ && queue_.empty() && !any_busy())) {
    if (stopping_)
      std::this_thread::sleep_for(kPollPause);
    else
      read_orchestrator();  // waits up to kPollPause for input
    collect_answers();
    dispatch();
  }
  for (int rank = 1; rank < mpi_.size(); ++rank) send_text(rank, kTagStop, {});
}

void Broker::read_orchestrator() {
  for (const std::string& line : input_.read(kPollPause)) {
    handle_line(line);
    if (stopping_) return;  // lines after a stop are not read
  }
  if (input_.ended() && !stopping_)
    mpi_.abort("stdin ended without a stop message: the orchestrator is gone; aborting the job");
}

void Broker::handle_line(const std::string& line) {
  if (line.find_first_not_of(" \t") == std::string::npos) return;
  try {
    const OrchestratorMessage message = decode_orchestrator_line(line);
    if (const auto* assignment = std::get_if<CaseAssignment>(&message))
      queue_.push_back(*assignment);
    else if (const auto* malformed = std::get_if<MalformedAssignment>(&message))
      out_.send(answer_malformed(*malformed, 0));
    else
      stopping_ = true;
  } catch (const ProtocolError& e) {
    out_.send(protocol_error_message(e.what()));
  }
}

void Broker::collect_answers() {
  while (auto answer = try_receive_text(MPI_ANY_SOURCE, kTagAnswer)) {
    out_.send_serialized(answer->text);
    busy_[static_cast<std::size_t>(answer->source)] = false;
  }
  if (auto answer = local_.take_answer()) {
    out_.send_serialized(*answer);
    busy_[0] = false;
  }
}

void Broker::dispatch() {
  for (int rank = idle_rank(); rank >= 0 && !queue_.empty(); rank = idle_rank()) {
    CaseAssignment assignment = std::move(queue_.front());
    queue_.pop_front();
    busy_[static_cast<std::size_t>(rank)] = true;
    // An idle rank begins a case the moment it receives it (a worker rank looks every kPollPause).
    out_.send(started_message(assignment.case_id, assignment.attempt, rank, hosts_[static_cast<std::size_t>(rank)]));
    if (rank == 0)
      local_.start(std::move(assignment));
    else
      send_text(rank, kTagCase, serialize_message(to_json(assignment)));
  }
}

int Broker::idle_rank() const {
  // The other ranks first: rank 0's core also carries this loop.
  for (int rank = 1; rank < mpi_.size(); ++rank)
    if (!busy_[static_cast<std::size_t>(rank)]) return rank;
  return busy_[0] ? -1 : 0;
}

bool Broker::any_busy() const { return std::any_of(busy_.begin(), busy_.end(), [](bool b) { return b; }); }

}  // namespace aerobreak
