#include "orchestrator/worker/broker.hpp"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <thread>
#include <variant>

#include "orchestrator/worker/case_answer.hpp"
#include "orchestrator/worker/mpi_text.hpp"

namespace aerobreak {
namespace {

double seconds_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

}  // namespace

Broker::Broker(const MpiSession& mpi, ProtocolOutput& out, std::vector<std::string> hosts,
               std::chrono::milliseconds silence_limit)
    : mpi_(mpi),
      out_(out),
      hosts_(std::move(hosts)),
      silence_limit_(silence_limit),
      input_(STDIN_FILENO),
      ranks_(static_cast<std::size_t>(mpi.size())),
      last_heartbeat_(Clock::now()),
      local_(0) {}

void Broker::run() {
  try {
    serve();
  } catch (const std::exception& e) {
    // Abort from here, while the case thread may still compute: unwinding past local_ would
    // first wait for its case to finish.
    mpi_.abort(e.what());
  }
  if (lost_ranks() > 0) mpi_.abort(std::to_string(lost_ranks()) + " rank(s) lost; ending without waiting for them");
}

void Broker::serve() {
  while (!(stopping_ && queue_.empty() && !any_busy())) {
    if (stopping_)
      std::this_thread::sleep_for(kPollPause);
    else
      read_orchestrator();  // waits up to kPollPause for input
    collect_answers();
    give_up_silent_ranks();
    dispatch();
    say_alive();
  }
  for (int rank = 1; rank < mpi_.size(); ++rank)
    if (!ranks_[static_cast<std::size_t>(rank)].lost) send_text(rank, kTagStop, {});
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
  // Worker ranks send two kinds of message: their answer, and kTagAlive while they run a case.
  while (auto message = try_receive_text(MPI_ANY_SOURCE, MPI_ANY_TAG)) {
    RankSlot& slot = ranks_[static_cast<std::size_t>(message->source)];
    slot.heard = Clock::now();
    // A rank given up may wake up with its answer: its case was answered as lost already.
    if (message->tag != kTagAnswer || slot.lost) continue;
    out_.send_serialized(message->text);
    slot.busy = false;
  }
  if (auto answer = local_.take_answer()) {
    out_.send_serialized(*answer);
    ranks_[0].busy = false;
  }
}

void Broker::give_up_silent_ranks() {
  const auto now = Clock::now();
  // Rank 0's own case runs in this process: its silence cannot be told from this loop's.
  for (int rank = 1; rank < mpi_.size(); ++rank) {
    RankSlot& slot = ranks_[static_cast<std::size_t>(rank)];
    if (!slot.busy || slot.lost || now - slot.heard <= silence_limit_) continue;
    slot.lost = true;
    const double silent = seconds_between(slot.heard, now);
    const std::string& host = hosts_[static_cast<std::size_t>(rank)];
    out_.send(rank_lost_message(rank, host, mpi_.size() - lost_ranks(), silent));
    char text[200];
    std::snprintf(text, sizeof text,
                  "rank %d on %s sent nothing for %.0f s while it ran the case (stopped, or its node lost or cut "
                  "off); the rank gets no more cases",
                  rank, host.c_str(), silent);
    out_.send(
        failed_message(slot.case_id, slot.attempt, rank, seconds_between(slot.handed, now), FailureKind::lost, text));
  }
}

void Broker::dispatch() {
  for (int rank = idle_rank(); rank >= 0 && !queue_.empty(); rank = idle_rank()) {
    CaseAssignment assignment = std::move(queue_.front());
    queue_.pop_front();
    RankSlot& slot = ranks_[static_cast<std::size_t>(rank)];
    // The rank answered its last case, so it took that case's hand-over: ending it does not wait.
    slot = {true, false, Clock::now(), Clock::now(), assignment.case_id, assignment.attempt, nullptr};
    // An idle rank begins a case the moment it receives it (a worker rank looks every kPollPause).
    out_.send(started_message(assignment.case_id, assignment.attempt, rank, hosts_[static_cast<std::size_t>(rank)]));
    if (rank == 0)
      local_.start(std::move(assignment));
    else
      slot.handover = std::make_unique<PendingSend>(rank, kTagCase, serialize_message(to_json(assignment)));
  }
}

void Broker::say_alive() {
  if (Clock::now() - last_heartbeat_ < kHeartbeatInterval) return;
  out_.send(heartbeat_message());
  last_heartbeat_ = Clock::now();
}

int Broker::idle_rank() const {
  // The other ranks first: rank 0's core also carries this loop. A lost rank stays busy.
  for (int rank = 1; rank < mpi_.size(); ++rank)
    if (!ranks_[static_cast<std::size_t>(rank)].busy) return rank;
  return ranks_[0].busy ? -1 : 0;
}

bool Broker::any_busy() const {
  return std::any_of(ranks_.begin(), ranks_.end(), [](const RankSlot& slot) { return slot.busy && !slot.lost; });
}

int Broker::lost_ranks() const {
  return static_cast<int>(std::count_if(ranks_.begin(), ranks_.end(), [](const RankSlot& slot) { return slot.lost; }));
}

}  // namespace aerobreak
