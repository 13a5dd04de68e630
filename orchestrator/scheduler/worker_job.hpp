#pragma once
#include <sys/types.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

// One running worker job (a launcher process and its ranks) seen from the orchestrator: its stdin
// takes protocol messages, its stdout yields them (docs/WORKER_PROTOCOL.md). Everything else the
// job prints (stderr, stray stdout lines) goes to `log_file`, so that it neither garbles the
// orchestrator's output nor gets lost.
//
// The job runs in a process group of its own, so that kill() reaches the launcher and every rank
// it started on this machine. If the orchestrator dies, the job's stdin closes and rank 0 aborts
// the job (the protocol's EOF rule); the launcher also gets SIGTERM through PR_SET_PDEATHSIG.
class WorkerJob {
 public:
  WorkerJob(const std::vector<std::string>& command, const std::filesystem::path& log_file);
  WorkerJob(const WorkerJob&) = delete;
  WorkerJob& operator=(const WorkerJob&) = delete;
  ~WorkerJob();  // kills the job if it still runs

  pid_t pid() const { return pid_; }

  // Writes one message; false when the job no longer reads (it ended).
  bool send(const nlohmann::ordered_json& message);
  // Closes the job's stdin (a job told to stop needs nothing more).
  void close_input();

  // The next message, decoded (decode_job_line), waiting at most `timeout`; nullopt on timeout or
  // once the job's output has ended and every message was taken.
  std::optional<JobMessage> next_message(std::chrono::milliseconds timeout);
  // The job's output has ended and every message was taken.
  bool finished();

  // Exit status once the process has ended (waitpid, non-blocking): the exit code, or 128 + signal.
  std::optional<int> exit_status();
  // Tells the job to stop (a stop message, then end of input) and waits up to `patience` for its
  // launcher to end by itself; true if it did.
  bool stop_within(std::chrono::milliseconds patience);
  // Ends the job: SIGTERM to its process group, so that the launcher ends its ranks and (srun)
  // its Slurm job step and allocation; SIGKILL to the group after kTerminationGrace, or once the
  // launcher has ended, for whatever is left on this machine. Reaps the launcher.
  void kill();
  static constexpr std::chrono::seconds kTerminationGrace{5};

 private:
  void read_output();
  void log_line(const std::string& line);

  pid_t pid_ = -1;
  int input_ = -1;
  int output_ = -1;
  std::optional<int> exit_status_;
  std::thread reader_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::deque<JobMessage> messages_;
  bool output_ended_ = false;
  int log_ = -1;  // O_APPEND: the job's stderr and the reader thread write whole lines to it
};

}  // namespace aerobreak
