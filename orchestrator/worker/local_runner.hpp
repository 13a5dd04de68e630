#pragma once
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

// Rank 0's own case slot: a thread that runs one assignment at a time while the main thread
// keeps brokering (and alone calls MPI). Hand-off both ways under one mutex; the answer waits
// until the broker takes it.
class LocalRunner {
 public:
  explicit LocalRunner(int rank);
  LocalRunner(const LocalRunner&) = delete;
  LocalRunner& operator=(const LocalRunner&) = delete;
  ~LocalRunner();  // finishes the case in hand, then joins the thread

  // Hands over an assignment; only while the runner is idle (its last answer taken).
  void start(CaseAssignment assignment);

  // The serialized answer to the assignment in hand, once it is finished.
  std::optional<std::string> take_answer();

 private:
  void run();

  const int rank_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<CaseAssignment> next_;
  std::optional<std::string> answer_;
  bool stopping_ = false;
  std::thread thread_;  // last: it starts once everything it uses exists
};

}  // namespace aerobreak
