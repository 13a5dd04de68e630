#include "orchestrator/scheduler/worker_job.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {
namespace {

int exit_code_of(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

void write_all(int fd, const std::string& text) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    written += static_cast<std::size_t>(n);
  }
}

// Whether the process has ended, leaving it unreaped (its id stays taken).
bool launcher_ended(pid_t pid) {
  siginfo_t info{};
  return ::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

// Open MPI refuses to start as root unless told; the orchestrator runs where its user runs it
// (containers and CI run as root), so it says so for the jobs it starts.
void allow_mpirun_as_root() {
  if (::geteuid() != 0) return;
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
}

}  // namespace

WorkerJob::WorkerJob(const std::vector<std::string>& command, const std::filesystem::path& log_file) {
  if (command.empty()) throw std::invalid_argument("empty worker job command");
  if (log_file.has_parent_path()) std::filesystem::create_directories(log_file.parent_path());
  log_ = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log_ < 0) throw std::runtime_error("cannot open the job log " + log_file.string() + ": " + std::strerror(errno));
  // A job that has ended must not kill the orchestrator with SIGPIPE when it is written to.
  ::signal(SIGPIPE, SIG_IGN);

  int to_job[2];
  int from_job[2];
  if (::pipe2(to_job, O_CLOEXEC) != 0 || ::pipe2(from_job, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot create pipes for a worker job: ") + std::strerror(errno));

  std::vector<char*> argv;
  for (const auto& word : command) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error(std::string("cannot fork a worker job: ") + std::strerror(errno));
  if (pid_ == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(125);  // the orchestrator died before the line above
    // The orchestrator blocks its shut-down signals (to wait for them) and ignores SIGPIPE; the
    // job must get the defaults back, or it could not be stopped with SIGTERM or PDEATHSIG.
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::signal(SIGPIPE, SIG_DFL);
    ::dup2(to_job[0], STDIN_FILENO);
    ::dup2(from_job[1], STDOUT_FILENO);
    ::dup2(log_, STDERR_FILENO);
    allow_mpirun_as_root();
    ::execvp(argv[0], argv.data());
    const std::string message = std::string("cannot start ") + argv[0] + ": " + std::strerror(errno) + "\n";
    write_all(STDERR_FILENO, message);
    ::_exit(127);
  }
  ::setpgid(pid_, pid_);
  ::close(to_job[0]);
  ::close(from_job[1]);
  input_ = to_job[1];
  output_ = from_job[0];
  reader_ = std::thread([this] { read_output(); });
}

WorkerJob::~WorkerJob() {
  if (!exit_status()) kill();
  if (input_ >= 0) ::close(input_);
  reader_.join();
  ::close(output_);
  ::close(log_);
}

bool WorkerJob::send(const nlohmann::ordered_json& message) {
  if (input_ < 0) return false;
  const std::string line = protocol_line(message);
  std::size_t written = 0;
  while (written < line.size()) {
    const ssize_t n = ::write(input_, line.data() + written, line.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    written += static_cast<std::size_t>(n);
  }
  return true;
}

void WorkerJob::close_input() {
  if (input_ >= 0) ::close(input_);
  input_ = -1;
}

void WorkerJob::log_line(const std::string& line) { write_all(log_, line + "\n"); }

void WorkerJob::read_output() {
  std::string pending;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(output_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(buffer, static_cast<std::size_t>(n));
    std::size_t start = 0;
    for (std::size_t end; (end = pending.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string line = pending.substr(start, end - start);
      if (auto message = decode_job_line(line)) {
        std::lock_guard lock(mutex_);
        messages_.push_back(std::move(*message));
        arrived_.notify_all();
      } else if (!line.empty()) {
        log_line(line);
      }
    }
    pending.erase(0, start);
  }
  if (!pending.empty()) log_line(pending);
  std::lock_guard lock(mutex_);
  output_ended_ = true;
  arrived_.notify_all();
}

std::optional<JobMessage> WorkerJob::next_message(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  arrived_.wait_for(lock, timeout, [this] { return !messages_.empty() || output_ended_; });
  if (messages_.empty()) return std::nullopt;
  auto message = std::move(messages_.front());
  messages_.pop_front();
  return message;
}

bool WorkerJob::finished() {
  std::lock_guard lock(mutex_);
  return output_ended_ && messages_.empty();
}

std::optional<int> WorkerJob::exit_status() {
  if (exit_status_) return exit_status_;
  int status = 0;
  const pid_t reaped = ::waitpid(pid_, &status, WNOHANG);
  if (reaped == pid_) exit_status_ = exit_code_of(status);
  return exit_status_;
}

bool WorkerJob::stop_within(std::chrono::milliseconds patience) {
  send(to_json(StopRequest{}));
  close_input();
  const auto deadline = std::chrono::steady_clock::now() + patience;
  while (!exit_status() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return exit_status().has_value();
}

void WorkerJob::kill() {
  if (exit_status()) return;
  // SIGTERM first: the launcher then ends its ranks itself, on other machines too, and srun ends
  // the job step and gives back the allocation it made. An srun that got SIGKILL leaves that to
  // Slurm, which with the default InactiveLimit=0 keeps the job and its nodes until the job's time
  // limit (seen with tests/slurm/run_slurm_study.sh: RUNNING after `aerobreak run` had ended).
  ::kill(-pid_, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + kTerminationGrace;
  while (!launcher_ended(pid_) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  // Whatever of the group is left on this machine (or a launcher that ignored SIGTERM) ends now;
  // the launcher is reaped only after this, so that its id cannot name another process group.
  ::kill(-pid_, SIGKILL);
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  exit_status_ = exit_code_of(status);
}

}  // namespace aerobreak
