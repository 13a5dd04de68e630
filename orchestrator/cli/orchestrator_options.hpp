#pragma once
#include <CLI/CLI.hpp>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "orchestrator/scheduler/scheduler.hpp"
#include "orchestrator/service/service.hpp"

namespace aerobreak {

// The options `aerobreak serve` and `aerobreak run` share: where the store and bulk files live and
// how worker jobs are launched.
struct OrchestratorOptions {
  std::string store;
  std::string data;  // default: STORE without its extension + ".data"
  std::string launcher = "mpirun";
  int ranks = 0;  // 0: the machine's cores
  std::vector<std::string> launcher_arguments;
  double idle_shutdown = 10.0;                                               // seconds
  double silence_limit = static_cast<double>(kDefaultSilenceLimit.count());  // seconds
  std::string web_directory;   // the dashboard's folder; default: default_web_directory()
  std::string worker_program;  // what worker jobs run as `PROGRAM worker`; default: this executable

  void add_to(CLI::App& command);
  std::filesystem::path data_directory() const;
  SchedulerOptions scheduler_options(std::function<void(const std::string&)> log) const;
  // Service options with the dashboard's folder and the data folder (case files) set.
  ServiceOptions service_options() const;
};

// SIGINT and SIGTERM, blocked in the constructing thread (construct it before starting any thread,
// so that every thread inherits the mask) and taken synchronously: a shut-down then runs as
// ordinary code (stop the service, stop the scheduler, requeue) instead of in a signal handler.
class ShutdownSignals {
 public:
  ShutdownSignals();
  // Waits for SIGINT or SIGTERM and returns it.
  int wait();
  // Waits at most `timeout`; 0 when no signal came.
  int wait_for(std::chrono::milliseconds timeout);

 private:
  sigset_t signals_;
};

// Appends time-stamped lines to a file, or to stderr when the path is empty.
std::function<void(const std::string&)> line_log(const std::filesystem::path& file);

}  // namespace aerobreak
