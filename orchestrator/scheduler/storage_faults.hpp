#pragma once
#include <chrono>
#include <cstddef>
#include <deque>
#include <functional>
#include <optional>
#include <string>

namespace aerobreak {

// What the scheduler reports while storage is failing.
struct StorageFaultStatus {
  std::string error;               // the latest fault
  double since = 0.0;              // Unix seconds of the first fault of this spell
  std::size_t waiting_writes = 0;  // store writes held until the store takes them
};

// The scheduler's answer to storage that fails for a while (the store's disk full or read-only,
// I/O errors, a data directory that cannot be written): no case is failed for it, the service
// keeps running, and nothing is lost once storage works again.
//
// A store write refused for a storage fault (SqliteError::storage_fault) is kept, with every write
// after it, and retried in order; meanwhile, and for a delay after any fault (doubling from 1 s up
// to a maximum while faults go on), the scheduler hands out no case. If the orchestrator stops
// with writes still waiting, the cases they concern are still `running` in the store, and the
// next start queues them again without a failure counted.
class StorageFaults {
 public:
  using Clock = std::chrono::steady_clock;

  explicit StorageFaults(std::chrono::milliseconds max_delay) : max_delay_(max_delay) {}

  // Runs `write` now, or after the writes already waiting; keeps it when the store refuses it for
  // a storage fault. Any other exception propagates. True when no write is left waiting.
  bool write(std::function<void()> write);
  // A fault met elsewhere: a claim or launch the store refused, a data file a worker could not
  // write.
  void note(const std::string& error);
  // Retries the waiting writes once the delay has passed, or at once; true when none is left.
  bool retry_when_due();
  bool retry_now();
  // A result committed with nothing waiting: storage works again.
  void clear();

  // Whether new work must wait (writes waiting, or within the delay after a fault).
  bool holding() const;
  std::optional<StorageFaultStatus> status() const;

 private:
  std::chrono::milliseconds max_delay_;
  std::deque<std::function<void()>> waiting_;
  std::optional<StorageFaultStatus> fault_;
  std::chrono::milliseconds delay_{0};
  Clock::time_point retry_at_{};
};

}  // namespace aerobreak
