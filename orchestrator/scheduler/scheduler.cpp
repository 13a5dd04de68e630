#include "orchestrator/scheduler/scheduler.hpp"

#include <algorithm>

#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {
namespace {

using Clock = std::chrono::steady_clock;

std::optional<AttemptEnd> attempt_end_of(const std::string& kind) {
  if (kind == "invalid") return AttemptEnd::invalid;
  if (kind == "wall_time") return AttemptEnd::wall_time;
  if (kind == "error") return AttemptEnd::error;
  return std::nullopt;
}

std::string text_or(const nlohmann::json& message, const char* key, const std::string& fallback) {
  const auto found = message.find(key);
  return found != message.end() && found->is_string() ? found->get<std::string>() : fallback;
}

}  // namespace

Scheduler::Scheduler(Store& store, SchedulerOptions options)
    : store_(store), options_(std::move(options)), searches_(store, options_.log) {
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

void Scheduler::advance_searches() {
  if (!searches_due_) return;
  searches_due_ = false;
  try {
    searches_.advance();
  } catch (const std::exception& error) {
    note(std::string("adaptive search: ") + error.what());
  }
}

void Scheduler::run() {
  while (!stopping_) {
    advance_searches();
    if (job_) {
      // Wait for one message at most 50 ms, then take the ones already there without waiting:
      // each may free a rank, and the freed rank gets its next case right after.
      auto message = job_->next_message(std::chrono::milliseconds(50));
      while (message && !stopping_) {
        handle(*message);
        message = job_->next_message(std::chrono::milliseconds(0));
      }
      if (!stopping_) {
        feed_job();
        check_hard_limits();
        stop_idle_job();
        reap_job();
      }
    } else if (Clock::now() >= next_launch_ && store_.claimable_cases() > 0) {
      launch_job();
    } else {
      std::unique_lock lock(wake_mutex_);
      wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return woken_ || stopping_.load(); });
      woken_ = false;
      searches_due_ = true;
    }
  }
  if (job_) {
    job_->kill();
    store_.requeue_job(status_.job_id, "the orchestrator stopped", false);
    store_.end_job(status_.job_id, *job_->exit_status(), "killed: the orchestrator stopped");
    job_.reset();
  }
}

void Scheduler::launch_job() {
  const auto command = worker_job_command(options_.launcher);
  const auto job_id = store_.start_job(join_command(command), options_.launcher.ranks);
  const auto log_file = options_.data_directory / "logs" / ("job-" + std::to_string(job_id) + ".log");
  try {
    job_ = std::make_unique<WorkerJob>(command, log_file);
  } catch (const std::exception& error) {
    store_.end_job(job_id, -1, error.what());
    std::lock_guard lock(status_mutex_);
    status_.last_error = error.what();
    next_launch_ = Clock::now() + options_.max_launch_delay;
    return;
  }
  in_flight_.clear();
  job_told_to_stop_ = false;
  job_idle_since_ = Clock::now();
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
  if (!status.job_ready || job_told_to_stop_) return;
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

void Scheduler::handle(const nlohmann::json& message) {
  const std::string type = text_or(message, "type", "");
  if (type == "ready") {
    const int ranks = message.value("ranks", 0);
    store_.job_started(status().job_id, message.value("pid", std::int64_t{0}),
                       message.value("hosts", nlohmann::json::array()));
    std::lock_guard lock(status_mutex_);
    status_.job_ready = ranks > 0;
    status_.ranks = ranks;
    status_.consecutive_launch_failures = 0;
    return;
  }
  if (type == "protocol_error") {
    note("worker job reports a protocol error: " + text_or(message, "message", "(no message)"));
    return;
  }
  const auto case_id = message.value("case", std::int64_t{-1});
  const int attempt = message.value("attempt", -1);
  const auto flight = in_flight_.find(case_id);
  if (flight == in_flight_.end() || flight->second.attempt != attempt) {
    note("ignored a '" + type + "' message for case " + std::to_string(case_id) + " attempt " +
         std::to_string(attempt) + ", which this job does not run");
    return;
  }
  if (type == "started") {
    store_.record_worker(case_id, attempt,
                         text_or(message, "host", "?") + ":" + std::to_string(message.value("rank", -1)));
    return;
  }
  searches_due_ = true;
  if (type == "result") {
    try {
      const nlohmann::ordered_json result = message.at("result");
      if (store_.commit_result(case_id, attempt, result, text_or(message, "data_file", ""),
                               message.value("seconds", 0.0))) {
        std::lock_guard lock(status_mutex_);
        ++status_.results_committed;
      }
    } catch (const std::exception& error) {
      store_.record_failure(case_id, attempt, AttemptEnd::error, std::string("result refused: ") + error.what());
    }
  } else if (type == "failed") {
    const auto end = attempt_end_of(text_or(message, "kind", "error")).value_or(AttemptEnd::error);
    const std::string error = text_or(message, "error", "(no error text)");
    const auto status = store_.record_failure(case_id, attempt, end, error);
    note("case " + std::to_string(case_id) + " attempt " + std::to_string(attempt) + " failed (" +
         std::string(to_string(end)) + "): " + error +
         (status == CaseStatus::failed ? " - marked failed" : " - queued again"));
  } else {
    note("ignored a worker message of unknown type '" + type + "'");
    return;
  }
  in_flight_.erase(flight);
  std::lock_guard lock(status_mutex_);
  status_.in_flight = in_flight_.size();
}

void Scheduler::check_hard_limits() {
  if (overdue_case_) return;
  const auto now = Clock::now();
  for (const auto& [case_id, flight] : in_flight_) {
    if (flight.wall_time_limit <= 0.0) continue;
    const auto limit = std::chrono::duration<double>(flight.wall_time_limit * options_.hard_limit_factor) +
                       options_.hard_limit_margin;
    if (now - flight.sent > limit) {
      note("case " + std::to_string(case_id) + " ignored its wall-time limit; killing its worker job");
      overdue_case_ = case_id;
      job_->kill();
      return;
    }
  }
}

void Scheduler::stop_idle_job() {
  if (job_told_to_stop_ || !in_flight_.empty() || !status().job_ready) return;
  if (Clock::now() - job_idle_since_ < options_.idle_shutdown) return;
  if (store_.claimable_cases() > 0) {
    job_idle_since_ = Clock::now();
    return;
  }
  job_->send({{"type", "stop"}});
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
                                                         : "ended with exit status " + std::to_string(code);
  if (overdue_case_) {
    const auto& flight = in_flight_.at(*overdue_case_);
    store_.record_failure(*overdue_case_, flight.attempt, AttemptEnd::wall_time,
                          "still running " + std::to_string(flight.wall_time_limit * options_.hard_limit_factor) +
                              " s after its start (wall-time limit " + std::to_string(flight.wall_time_limit) +
                              " s); its worker job was killed");
    in_flight_.erase(*overdue_case_);
    store_.requeue_job(job_id, "worker job killed for another case's wall time", false);
    note_text = "killed: case " + std::to_string(*overdue_case_) + " overran its wall-time limit";
    overdue_case_.reset();
  } else if (!in_flight_.empty()) {
    const auto requeued = store_.requeue_job(job_id, "the worker job " + note_text + " while the case ran");
    note("worker job " + std::to_string(job_id) + " " + note_text + " with " + std::to_string(in_flight_.size()) +
         " case(s) in flight; " + std::to_string(requeued) + " queued again");
  }
  store_.end_job(job_id, code, note_text);
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
