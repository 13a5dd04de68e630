#pragma once
#include <sys/types.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "orchestrator/scheduler/launcher.hpp"
#include "orchestrator/scheduler/storage_faults.hpp"
#include "orchestrator/scheduler/worker_job.hpp"
#include "orchestrator/search/search_driver.hpp"
#include "orchestrator/store/store.hpp"
#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

struct SchedulerOptions {
  LauncherConfig launcher;
  // Bulk files: DATA/cases/HASH.h5 per finished case, DATA/logs/job-ID.log per worker job.
  std::filesystem::path data_directory;
  // A job with nothing to do for this long is stopped, so that an idle service holds no cores.
  std::chrono::milliseconds idle_shutdown{std::chrono::seconds(10)};
  // The workers stop a case at its wall-time limit themselves; a case still running at
  // limit x hard_limit_factor + hard_limit_margin is stuck where it cannot check the clock, and
  // its job is killed.
  double hard_limit_factor = 1.5;
  std::chrono::milliseconds hard_limit_margin{std::chrono::seconds(30)};
  // A ready job says something at least every kHeartbeatInterval; one silent for this long is taken
  // for lost (its launcher hangs on a lost node, or rank 0 is stopped or cut off) and killed, and its
  // cases go back to the queue as for a job that died.
  std::chrono::milliseconds silence_limit{kDefaultSilenceLimit};
  // Consecutive jobs that end before saying "ready" make the launcher count as failing; launches
  // are then retried with a growing delay, up to max_launch_delay.
  int launch_failures_reported = 3;
  std::chrono::milliseconds max_launch_delay{std::chrono::seconds(60)};
  // While storage fails (storage_faults.hpp), new work waits a delay that doubles up to this.
  std::chrono::milliseconds max_storage_retry_delay{std::chrono::seconds(16)};
  // Where the scheduler's one-line notes go (job started, case failed, ...).
  std::function<void(const std::string&)> log;
};

struct SchedulerStatus {
  std::string launcher_command;
  bool job_running = false;
  std::int64_t job_id = 0;
  pid_t job_pid = 0;
  int ranks = 0;
  bool job_ready = false;
  std::size_t in_flight = 0;
  std::size_t jobs_started = 0;
  std::size_t results_committed = 0;
  int consecutive_launch_failures = 0;
  std::string last_error;
  std::optional<StorageFaultStatus> storage_fault;  // the store or data directory cannot be written
};

// Hands the store's queued cases to worker jobs one case per free rank (dynamic: a rank asks for
// nothing, it gets the next case the moment it reports its last one), commits every result the
// moment it arrives, and turns every way a case or a job can end into a store transition
// (store.hpp). All of it on one thread, the store's one writer besides submissions and cancels.
// Storage that fails (disk full, read-only, I/O errors) fails no case and stops nothing: the
// scheduler holds its writes and new work until storage works again (storage_faults.hpp).
// Between messages it decides the adaptive searches' next rounds (search_driver.hpp) as their
// last rounds finish, so that their cases join the queue the moment they can be chosen.
class Scheduler {
 public:
  Scheduler(Store& store, SchedulerOptions options);
  ~Scheduler();
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  // Recovers what a previous orchestrator left running (store.requeue_interrupted) and starts the
  // scheduling thread.
  void start();
  // Stops the thread; a running job is killed and its cases requeued without a failure counted.
  void stop();
  // New work may be there (a study was submitted): look now instead of at the next poll.
  void wake();
  SchedulerStatus status() const;

 private:
  struct InFlight {
    int attempt = 0;
    double wall_time_limit = 0.0;
    std::chrono::steady_clock::time_point sent;
  };
  // A case the scheduler killed its job for, and how long it had run then.
  struct OverdueCase {
    std::int64_t case_id = 0;
    double seconds = 0.0;
  };

  void run();
  void step();
  void end_job_on_stop();
  void launch_job();
  void feed_job();
  using Flight = std::map<std::int64_t, InFlight>::iterator;
  // One handler per message type of the worker protocol (worker_protocol.hpp).
  void handle(JobMessage& message);
  void handle(const JobReady& ready);
  void handle(const JobProtocolError& error);
  void handle(const UnknownJobMessage& message);
  void handle(const JobHeartbeat& heartbeat);
  void handle(const RankLost& lost);
  void handle(const CaseStarted& started);
  void handle(CaseResult& result);
  void handle(const CaseFailed& failed);
  void handle(const UnreadableAnswer& answer);
  // The case a message is about, in flight on this job; in_flight_.end() (and a log line) otherwise.
  Flight flight_of(const std::string& type, std::int64_t case_id, int attempt);
  // The case's answer has been dealt with: it is no longer in flight.
  void landed(Flight flight);
  void commit_result(const CaseResult& result);
  void record_failure(std::int64_t case_id, int attempt, AttemptEnd end, const std::string& error);
  void publish_storage_status();
  void check_hard_limits();
  void check_silence();
  void stop_idle_job();
  void reap_job();
  void advance_searches();
  void note(const std::string& line);

  Store& store_;
  SchedulerOptions options_;
  std::thread thread_;
  std::atomic<bool> stopping_{false};
  std::mutex wake_mutex_;
  std::condition_variable wake_;
  bool woken_ = false;

  // Scheduling thread only.
  SearchDriver searches_;
  bool searches_due_ = true;  // a case of a search may have finished: look for rounds to decide
  std::unique_ptr<WorkerJob> job_;
  std::map<std::int64_t, InFlight> in_flight_;
  std::optional<OverdueCase> overdue_case_;
  StorageFaults storage_;
  bool job_told_to_stop_ = false;
  bool job_silent_ = false;  // killed for its silence
  std::chrono::steady_clock::time_point job_heard_;
  std::chrono::steady_clock::time_point job_idle_since_;
  std::chrono::steady_clock::time_point next_launch_;

  mutable std::mutex status_mutex_;
  SchedulerStatus status_;
};

}  // namespace aerobreak
