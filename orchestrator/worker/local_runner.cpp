#include "orchestrator/worker/local_runner.hpp"

#include <stdexcept>

#include "orchestrator/worker/case_answer.hpp"

namespace aerobreak {

LocalRunner::LocalRunner(int rank) : rank_(rank), thread_([this] { run(); }) {}

LocalRunner::~LocalRunner() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void LocalRunner::start(CaseAssignment assignment) {
  {
    const std::lock_guard lock(mutex_);
    if (next_ || answer_) throw std::logic_error("LocalRunner::start while a case is in hand");
    next_ = std::move(assignment);
  }
  wake_.notify_one();
}

std::optional<std::string> LocalRunner::take_answer() {
  const std::lock_guard lock(mutex_);
  std::optional<std::string> answer = std::move(answer_);
  answer_.reset();
  return answer;
}

void LocalRunner::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || next_.has_value(); });
    if (!next_) return;
    const CaseAssignment assignment = *next_;
    lock.unlock();
    std::string answer = serialize_message(answer_assignment(assignment, rank_));
    lock.lock();
    next_.reset();
    answer_ = std::move(answer);
  }
}

}  // namespace aerobreak
