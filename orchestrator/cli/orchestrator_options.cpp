#include "orchestrator/cli/orchestrator_options.hpp"

#include <signal.h>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>

#include "orchestrator/store/data_paths.hpp"

namespace aerobreak {

void OrchestratorOptions::add_to(CLI::App& command) {
  command.add_option("--store", store, "SQLite store file (created when absent)")->capture_default_str();
  command.add_option("--data", data, "Folder for bulk HDF5 files and worker job logs [default: STORE.data]");
  command.add_option("--launcher", launcher, "How worker jobs start: mpirun, srun (Slurm) or direct (one process)")
      ->check(CLI::IsMember(launcher_kinds()))
      ->capture_default_str();
  command.add_option("--ranks", ranks, "MPI ranks of a worker job [default: the machine's cores]")
      ->check(CLI::Range(1, 100000));
  command
      .add_option("--launcher-arg", launcher_arguments,
                  "An argument for the launcher before the program, e.g. --launcher-arg=--hostfile "
                  "--launcher-arg=hosts (repeatable)")
      ->allow_extra_args(false);
  command.add_option("--idle-shutdown", idle_shutdown, "Seconds an idle worker job waits for work before it stops")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      .add_option("--silence-limit", silence_limit,
                  "Seconds a worker job, or a rank running a case, may send nothing before it is taken for lost "
                  "(a lost node, a stopped process): its cases go back to the queue")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      .add_option("--worker-program", worker_program,
                  "The program worker jobs run as PROGRAM worker [default: this aerobreak]; the tests' engine "
                  "double build/tests/aerobreak_synthetic_worker answers from a synthetic law (docs/ADAPTIVE.md)")
      ->check(CLI::ExistingFile);
  web_directory = default_web_directory().string();
  command.add_option("--web-dir", web_directory, "The dashboard's folder, served at / (empty: the API only)")
      ->capture_default_str();
}

ServiceOptions OrchestratorOptions::service_options() const {
  ServiceOptions options;
  options.web_directory = web_directory;
  options.data_directory = std::filesystem::absolute(data_directory());
  return options;
}

std::filesystem::path OrchestratorOptions::data_directory() const {
  return data.empty() ? default_data_directory(store) : std::filesystem::path(data);
}

SchedulerOptions OrchestratorOptions::scheduler_options(std::function<void(const std::string&)> log) const {
  SchedulerOptions options;
  options.launcher.kind = launcher;
  options.launcher.ranks =
      ranks > 0 ? ranks
                : (launcher == "direct" ? 1 : std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  options.launcher.arguments = launcher_arguments;
  options.launcher.program = worker_program.empty() ? current_executable() : std::filesystem::absolute(worker_program);
  options.data_directory = std::filesystem::absolute(data_directory());
  options.idle_shutdown = std::chrono::milliseconds(static_cast<long>(idle_shutdown * 1000.0));
  options.launcher.silence_limit = silence_limit;
  options.silence_limit = std::chrono::milliseconds(static_cast<long>(silence_limit * 1000.0));
  options.log = std::move(log);
  return options;
}

ShutdownSignals::ShutdownSignals() {
  sigemptyset(&signals_);
  sigaddset(&signals_, SIGINT);
  sigaddset(&signals_, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals_, nullptr);
}

int ShutdownSignals::wait() {
  int received = 0;
  sigwait(&signals_, &received);
  return received;
}

int ShutdownSignals::wait_for(std::chrono::milliseconds timeout) {
  const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(timeout);
  const timespec limit{static_cast<time_t>(seconds.count()),
                       static_cast<long>(std::chrono::nanoseconds(timeout - seconds).count())};
  const int received = sigtimedwait(&signals_, nullptr, &limit);
  return received > 0 ? received : 0;
}

std::function<void(const std::string&)> line_log(const std::filesystem::path& file) {
  auto out = std::make_shared<std::ofstream>();
  if (!file.empty()) {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    out->open(file, std::ios::app);
    if (!*out) throw std::runtime_error("cannot write the log " + file.string());
  }
  auto mutex = std::make_shared<std::mutex>();
  // The access log calls this once per request: the line is put together first and written in one
  // piece (std::cerr is unbuffered: each << would be a system call of its own).
  return [out, mutex](const std::string& line) {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S ", ::localtime_r(&now, &local));
    const std::string text = stamp + line + "\n";
    std::lock_guard lock(*mutex);
    std::ostream& stream = out->is_open() ? static_cast<std::ostream&>(*out) : std::cerr;
    stream.write(text.data(), static_cast<std::streamsize>(text.size()));
    stream.flush();
  };
}

}  // namespace aerobreak
