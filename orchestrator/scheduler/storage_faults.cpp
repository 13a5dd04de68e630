#include "orchestrator/scheduler/storage_faults.hpp"

#include <algorithm>

#include "orchestrator/store/sqlite_database.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

bool StorageFaults::write(std::function<void()> write) {
  waiting_.push_back(std::move(write));
  return waiting_.size() == 1 ? retry_now() : false;
}

void StorageFaults::note(const std::string& error) {
  if (!fault_) {
    fault_ = StorageFaultStatus{error, unix_seconds(), 0};
    delay_ = std::chrono::seconds(1);
  } else {
    fault_->error = error;
    delay_ = std::min(delay_ * 2, max_delay_);
  }
  retry_at_ = Clock::now() + delay_;
}

bool StorageFaults::retry_when_due() {
  if (waiting_.empty()) return true;
  return Clock::now() >= retry_at_ && retry_now();
}

void StorageFaults::clear() {
  if (!waiting_.empty()) return;
  fault_.reset();
  delay_ = std::chrono::milliseconds(0);
}

bool StorageFaults::holding() const { return fault_ && (!waiting_.empty() || Clock::now() < retry_at_); }

std::optional<StorageFaultStatus> StorageFaults::status() const {
  if (!fault_) return std::nullopt;
  StorageFaultStatus status = *fault_;
  status.waiting_writes = waiting_.size();
  return status;
}

bool StorageFaults::retry_now() {
  while (!waiting_.empty()) {
    try {
      waiting_.front()();
    } catch (const SqliteError& error) {
      if (error.storage_fault()) {
        note(error.what());
        return false;
      }
      waiting_.pop_front();
      throw;
    }
    waiting_.pop_front();
  }
  return true;
}

}  // namespace aerobreak
