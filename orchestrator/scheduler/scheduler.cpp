#include "orchestrator/scheduler/scheduler.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <variant>

#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {
namespace {

using Clock = std::chrono::steady_clock;

// "still running 47.3 s after its start (wall-time limit 10 s); its worker job was killed".
std::string overdue_text(double seconds, double limit) {
  char text[160];
  std::snprintf(text, sizeof text,
                "still running %.1f s after its start (wall-time limit %.6g s); its worker job was killed", seconds,
                limit);
  return text;
}

}  // namespace

Scheduler::Scheduler(Store& store, SchedulerOptions options)
    : store_(store),
      options_(std::move(options)),
      searches_(store, options_.log),
      storage_(options_.max_storage_retry_delay) {
  status_.launcher_command = join_command(worker_job_command(options_.launcher));
}

Scheduler::~Scheduler() { stop(); }

void Scheduler::start() {
  const auto requeued = store_.requeue_interrupted();
  const auto orphaned = store_.close_orphaned_jobs();
  if (requeued > 0 || orphaned > 0)
    note("recovered " + std::to_string(requeued) + " case(s) and " + std::to_string(orphaned) +
         " job(s) left running by an earlier orchestrator");
  thread_ = std::thread([this] { run(); });
}

void Scheduler::stop() {
  if (!thread_.joinable()) return;
  stopping_ = true;
  wake();
  thread_.join();
}

void Scheduler::wake() {
  std::lock_guard lock(wake_mutex_);
  woken_ = true;
  wake_.notify_all();
}

SchedulerStatus Scheduler::status() const {
  std::lock_guard lock(status_mutex_);
  return status_;
}

void Scheduler::note(const std::string& line) {
  if (options_.log) options_.log(line);
}

// A round the store refuses for a storage fault is not lost: it is decided again, from the same
// stored results, once storage works.
void Scheduler::advance_searches() {
  if (!searches_due_ || storage_.holding()) return;
  try {
    searches_.advance();
  } catch (const SqliteError& error) {
    if (error.storage_fault()) {
      storage_.note(error.what());
      return;
    }
    note(std::string("adaptive search: ") + error.what());
  } catch (const std::exception& error) {
    note(std::string("adaptive search: ") + error.what());
  }
  searches_due_ = false;
}

void Scheduler::run() {
  while (!stopping_) {
    try {
      step();
    } catch (const SqliteError& error) {
      // A read, claim or launch the store refused: nothing was changed; new work waits.
      if (!error.storage_fault()) throw;
      storage_.note(error.what());
    }
    publish_storage_status();
  }
  end_job_on_stop();
}

void Scheduler::step() {
  const bool writes_waiting = storage_.status() && storage_.status()->waiting_writes > 0;
  if (storage_.retry_when_due() && writes_waiting) storage_.clear();
  advance_searches();
  if (job_) {
    // Wait for one message at most 50 ms, then take the ones already there without waiting:
    // each may free a rank, and the freed rank gets its next case right after.
    auto message = job_->next_message(std::chrono::milliseconds(50));
    while (message && !stopping_) {
      job_heard_ = Clock::now();
      handle(*message);
      message = job_->next_message(std::chrono::milliseconds(0));
    }
    if (!stopping_) {
      feed_job();
      check_hard_limits();
      check_silence();
      stop_idle_job();
      reap_job();
    }
  } else if (!storage_.holding() && Clock::now() >= next_launch_ && store_.claimable_cases() > 0) {
    launch_job();
  } else {
    std::unique_lock lock(wake_mutex_);
    wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return woken_ || stopping_.load(); });
    woken_ = false;
    searches_due_ = true;
  }
}

void Scheduler::end_job_on_stop() {
  const bool written = storage_.retry_now();
  if (job_) {
    // A job with no case in flight is told to stop and ends by itself (srun then ends its step and
    // gives its allocation back before the orchestrator goes); one that does not in time is killed.
    const bool stopped = in_flight_.empty() && status().job_ready && job_->stop_within(WorkerJob::kTerminationGrace);
    if (!stopped) job_->kill();
    try {
      store_.requeue_job(status_.job_id, "the orchestrator stopped", false);
      store_.end_job(status_.job_id, *job_->exit_status(),
                     stopped ? "stopped with the orchestrator" : "killed: the orchestrator stopped");
    } catch (const SqliteError& error) {
      if (!error.storage_fault()) throw;
      note(std::string("could not record the end of the worker job: ") + error.what());
    }
    job_.reset();
  }
  if (!written)
    note(
        "stopped with store writes the store would not take; the cases they concern are still running in the "
        "store, and the next start queues them again without a failure");
}

void Scheduler::publish_storage_status() {
  const auto fault = storage_.status();
  if (fault && !status().storage_fault)
    note("storage fails (" + fault->error + "): no case is handed out until it works again; none is failed for it");
  if (!fault && status().storage_fault) note("storage works again; the store writes held meanwhile are committed");
  std::lock_guard lock(status_mutex_);
  status_.storage_fault = fault;
}

void Scheduler::launch_job() {
  const auto command = worker_job_command(options_.launcher);
  const auto job_id = store_.start_job(join_command(command), options_.launcher.ranks);
  const auto log_file = options_.data_directory / "logs" / ("job-" + std::to_string(job_id) + ".log");
  try {
    job_ = std::make_unique<WorkerJob>(command, log_file);
  } catch (const std::exception& error) {
    storage_.write([this, job_id, text = std::string(error.what())] { store_.end_job(job_id, -1, text); });
    std::lock_guard lock(status_mutex_);
    status_.last_error = error.what();
    next_launch_ = Clock::now() + options_.max_launch_delay;
    return;
  }
  in_flight_.clear();
  job_told_to_stop_ = false;
  job_silent_ = false;
  job_idle_since_ = Clock::now();
  job_heard_ = Clock::now();
  {
    std::lock_guard lock(status_mutex_);
    status_.job_running = true;
    status_.job_ready = false;
    status_.job_id = job_id;
    status_.job_pid = job_->pid();
    status_.ranks = 0;
    status_.in_flight = 0;
    ++status_.jobs_started;
  }
  note("worker job " + std::to_string(job_id) + " started: " + join_command(command) + " (log " + log_file.string() +
       ")");
}

void Scheduler::feed_job() {
  const auto status = this->status();
  if (!status.job_ready || job_told_to_stop_ || storage_.holding()) return;
  while (in_flight_.size() < static_cast<std::size_t>(status.ranks)) {
    auto assignment = store_.claim_next_case(status.job_id);
    if (!assignment) break;
    const auto data_file = options_.data_directory / "cases" / (assignment->hash + ".h5");
    const CaseAssignment message{assignment->case_id, assignment->attempt, assignment->document,
                                 assignment->wall_time_limit, data_file.string()};
    const bool sent = job_->send(to_json(message));
    // Unsent or not, the case is the job's now: if the job is gone, reaping it requeues the case.
    in_flight_[assignment->case_id] = {assignment->attempt, assignment->wall_time_limit, Clock::now()};
    if (!sent) break;
  }
  if (!in_flight_.empty()) job_idle_since_ = Clock::now();
  std::lock_guard lock(status_mutex_);
  status_.in_flight = in_flight_.size();
}

void Scheduler::handle(JobMessage& message) {
  std::visit([this](auto& each) { handle(each); }, message);
}

void Scheduler::handle(const JobReady& ready) {
  storage_.write([this, job_id = status().job_id, pid = ready.pid, hosts = nlohmann::ordered_json(ready.hosts)] {
    store_.job_started(job_id, pid, hosts);
  });
  std::lock_guard lock(status_mutex_);
  status_.job_ready = true;
  status_.ranks = ready.ranks;
  status_.consecutive_launch_failures = 0;
}

void Scheduler::handle(const JobProtocolError& error) { note("worker job reports a protocol error: " + error.message); }

void Scheduler::handle(const UnknownJobMessage& message) { note("ignored a worker message: " + message.problem); }

void Scheduler::handle(const JobHeartbeat&) {}  // every message counts as a sign of life (step())

// Rank 0 gave up a rank that went silent; its case comes as a failure of kind lost.
void Scheduler::handle(const RankLost& lost) {
  note("worker job " + std::to_string(status().job_id) + " lost rank " + std::to_string(lost.rank) + " on " +
       lost.host + " (silent for " + std::to_string(std::lround(lost.silent_seconds)) + " s); " +
       std::to_string(lost.ranks) + " rank(s) left");
  std::lock_guard lock(status_mutex_);
  status_.ranks = std::min(status_.ranks, lost.ranks);
}

Scheduler::Flight Scheduler::flight_of(const std::string& type, std::int64_t case_id, int attempt) {
  const auto flight = in_flight_.find(case_id);
  if (flight != in_flight_.end() && flight->second.attempt == attempt) return flight;
  note("ignored a '" + type + "' message for case " + std::to_string(case_id) + " attempt " + std::to_string(attempt) +
       ", which this job does not run");
  return in_flight_.end();
}

void Scheduler::landed(Flight flight) {
  in_flight_.erase(flight);
  searches_due_ = true;
  std::lock_guard lock(status_mutex_);
  status_.in_flight = in_flight_.size();
}

void Scheduler::handle(const CaseStarted& started) {
  if (flight_of("started", started.case_id, started.attempt) == in_flight_.end()) return;
  storage_.write(
      [this, case_id = started.case_id, attempt = started.attempt,
       worker = started.host + ":" + std::to_string(started.rank)] { store_.record_worker(case_id, attempt, worker); });
}

void Scheduler::handle(CaseResult& result) {
  const auto flight = flight_of("result", result.case_id, result.attempt);
  if (flight == in_flight_.end()) return;
  // Held, with the writes after it, while storage fails: kept once, not copied per retry.
  auto kept = std::make_shared<const CaseResult>(std::move(result));
  if (storage_.write([this, kept] { commit_result(*kept); })) storage_.clear();
  landed(flight);
}

void Scheduler::handle(const CaseFailed& failed) {
  const auto flight = flight_of("failed", failed.case_id, failed.attempt);
  if (flight == in_flight_.end()) return;
  if (failed.kind == FailureKind::storage) {
    // The worker could not write the case's data file: not the case's fault.
    storage_.write([this, case_id = failed.case_id, attempt = failed.attempt, error = failed.error] {
      store_.requeue_attempt(case_id, attempt, "its data file could not be written: " + error);
    });
    storage_.note(failed.error);
  } else {
    const AttemptEnd end = failed.kind == FailureKind::invalid     ? AttemptEnd::invalid
                           : failed.kind == FailureKind::wall_time ? AttemptEnd::wall_time
                           : failed.kind == FailureKind::lost      ? AttemptEnd::lost
                                                                   : AttemptEnd::error;
    record_failure(failed.case_id, failed.attempt, end, failed.error);
  }
  landed(flight);
}

// A result or failure that cannot be read fails the attempt rather than leave the case in flight;
// a start that cannot be read only goes unrecorded.
void Scheduler::handle(const UnreadableAnswer& answer) {
  const auto flight = flight_of(answer.type, answer.case_id, answer.attempt);
  if (flight == in_flight_.end()) return;
  if (answer.type == "started") {
    note("ignored a 'started' message for case " + std::to_string(answer.case_id) + ": " + answer.problem);
    return;
  }
  record_failure(answer.case_id, answer.attempt, AttemptEnd::error,
                 "the worker's '" + answer.type + "' message could not be read: " + answer.problem);
  landed(flight);
}

void Scheduler::commit_result(const CaseResult& result) {
  try {
    if (store_.commit_result(result.case_id, result.attempt, result.result, result.data_file, result.seconds,
                             {result.data_file_size, result.data_file_sha256})) {
      std::lock_guard lock(status_mutex_);
      ++status_.results_committed;
    }
  } catch (const SqliteError& error) {
    if (error.storage_fault()) throw;
    store_.record_failure(result.case_id, result.attempt, AttemptEnd::error,
                          std::string("result refused: ") + error.what());
  } catch (const std::exception& error) {
    store_.record_failure(result.case_id, result.attempt, AttemptEnd::error,
                          std::string("result refused: ") + error.what());
  }
}

void Scheduler::record_failure(std::int64_t case_id, int attempt, AttemptEnd end, const std::string& error) {
  storage_.write([this, case_id, attempt, end, error] {
    const auto status = store_.record_failure(case_id, attempt, end, error);
    note("case " + std::to_string(case_id) + " attempt " + std::to_string(attempt) + " failed (" +
         std::string(to_string(end)) + "): " + error +
         (status == CaseStatus::failed ? " - marked failed" : " - queued again"));
  });
}

void Scheduler::check_hard_limits() {
  if (overdue_case_) return;
  const auto now = Clock::now();
  for (const auto& [case_id, flight] : in_flight_) {
    if (flight.wall_time_limit <= 0.0) continue;
    const auto limit =
        std::chrono::duration<double>(flight.wall_time_limit * options_.hard_limit_factor) + options_.hard_limit_margin;
    if (now - flight.sent > limit) {
      note("case " + std::to_string(case_id) + " ignored its wall-time limit; killing its worker job");
      overdue_case_ = OverdueCase{case_id, std::chrono::duration<double>(now - flight.sent).count()};
      job_->kill();
      return;
    }
  }
}

// A ready job that has said nothing (not even its heartbeat) for the silence limit is taken for
// lost: seen with srun, which stayed running after Slurm had ended the job for a node failure
// (tests/slurm/run_slurm_cluster.sh), holding its cases as running for ever.
void Scheduler::check_silence() {
  if (job_silent_ || !status().job_ready || Clock::now() - job_heard_ <= options_.silence_limit) return;
  const auto silent = std::chrono::duration<double>(Clock::now() - job_heard_).count();
  note("worker job " + std::to_string(status().job_id) + " has sent nothing for " +
       std::to_string(std::lround(silent)) + " s; killing it");
  job_silent_ = true;
  job_->kill();
}

void Scheduler::stop_idle_job() {
  if (job_told_to_stop_ || !in_flight_.empty() || !status().job_ready) return;
  if (Clock::now() - job_idle_since_ < options_.idle_shutdown) return;
  if (store_.claimable_cases() > 0) {
    job_idle_since_ = Clock::now();
    return;
  }
  job_->send(to_json(StopRequest{}));
  job_->close_input();
  job_told_to_stop_ = true;
}

void Scheduler::reap_job() {
  if (!job_->finished()) return;
  auto exit_status = job_->exit_status();
  for (int wait = 0; !exit_status && wait < 100; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    exit_status = job_->exit_status();
  }
  if (!exit_status) job_->kill();
  const int code = *job_->exit_status();
  const auto job_id = status().job_id;
  const bool was_ready = status().job_ready;
  std::string note_text = job_told_to_stop_ && code == 0 ? "stopped when idle"
                          : job_silent_                  ? "was killed after sending nothing for the silence limit"
                                                         : "ended with exit status " + std::to_string(code);
  if (overdue_case_) {
    const auto& flight = in_flight_.at(overdue_case_->case_id);
    record_failure(overdue_case_->case_id, flight.attempt, AttemptEnd::wall_time,
                   overdue_text(overdue_case_->seconds, flight.wall_time_limit));
    in_flight_.erase(overdue_case_->case_id);
    storage_.write(
        [this, job_id] { store_.requeue_job(job_id, "worker job killed for another case's wall time", false); });
    note_text = "killed: case " + std::to_string(overdue_case_->case_id) + " overran its wall-time limit";
    overdue_case_.reset();
  } else if (!in_flight_.empty()) {
    storage_.write([this, job_id, note_text, in_flight = in_flight_.size()] {
      const auto requeued = store_.requeue_job(job_id, "the worker job " + note_text + " while the case ran");
      note("worker job " + std::to_string(job_id) + " " + note_text + " with " + std::to_string(in_flight) +
           " case(s) in flight; " + std::to_string(requeued) + " queued again");
    });
  }
  storage_.write([this, job_id, code, note_text] { store_.end_job(job_id, code, note_text); });
  job_.reset();
  in_flight_.clear();
  searches_due_ = true;

  std::lock_guard lock(status_mutex_);
  status_.job_running = false;
  status_.job_ready = false;
  status_.job_pid = 0;
  status_.in_flight = 0;
  if (!was_ready) {
    // It never started: a launcher or environment problem. Back off, doubling up to the maximum.
    ++status_.consecutive_launch_failures;
    status_.last_error = "worker job " + std::to_string(job_id) + " " + note_text + " before it was ready; see " +
                         (options_.data_directory / "logs" / ("job-" + std::to_string(job_id) + ".log")).string();
    const auto delay = std::min<std::chrono::milliseconds>(
        options_.max_launch_delay,
        std::chrono::milliseconds(500) * (1 << std::min(status_.consecutive_launch_failures, 10)));
    next_launch_ = Clock::now() + delay;
    if (status_.consecutive_launch_failures >= options_.launch_failures_reported) note(status_.last_error);
  }
}

}  // namespace aerobreak
