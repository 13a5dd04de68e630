#pragma once
// A real worker job for the tests: `mpirun -np K aerobreak worker` with pipes on its stdin and
// stdout, as the orchestrator runs it.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

extern char** environ;

namespace aerobreak::testing {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The live processes (zombies have no environment) whose environment holds `marker`: every
// process of one job, which inherit it from the mpirun the test started.
inline std::vector<pid_t> processes_with_marker(const std::string& marker) {
  std::vector<pid_t> found;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream environment(entry.path() / "environ", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(environment)), std::istreambuf_iterator<char>());
    if (text.find(marker) != std::string::npos) found.push_back(static_cast<pid_t>(std::stoi(name)));
  }
  return found;
}

// How the job is started: under mpirun, or as the program alone (an Open MPI singleton).
enum class Launch { mpirun, direct };

class WorkerJob {
 public:
  explicit WorkerJob(int ranks, Launch launch = Launch::mpirun, std::vector<std::string> worker_arguments = {}) {
    // A job that dies must fail the test through write()'s status, not kill it with SIGPIPE.
    ::signal(SIGPIPE, SIG_IGN);
    static std::atomic<int> counter{0};
    const std::string id = std::to_string(::getpid()) + "_" + std::to_string(counter++);
    marker_ = "AEROBREAK_WORKER_TEST_JOB=" + id;
    stderr_path_ = std::filesystem::temp_directory_path() / ("aerobreak_worker_test_" + id + ".err");

    int to_job[2], from_job[2];
    REQUIRE(::pipe2(to_job, O_CLOEXEC) == 0);
    REQUIRE(::pipe2(from_job, O_CLOEXEC) == 0);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_adddup2(&files, to_job[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&files, from_job[1], STDOUT_FILENO);
    posix_spawn_file_actions_addopen(&files, STDERR_FILENO, stderr_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    // A process group of its own, so that the test can end the whole job if it must.
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);

    std::vector<std::string> arguments{AEROBREAK_BINARY, "worker"};
    arguments.insert(arguments.end(), worker_arguments.begin(), worker_arguments.end());
    if (launch == Launch::mpirun)
      arguments.insert(arguments.begin(), {"mpirun", "--oversubscribe", "-np", std::to_string(ranks)});
    std::vector<std::string> environment{marker_, "OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"};
    for (char** e = environ; *e; ++e) environment.emplace_back(*e);
    const int spawned = ::posix_spawnp(&pid_, arguments.front().c_str(), &files, &attributes,
                                       pointers(arguments).data(), pointers(environment).data());
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    ::close(to_job[0]);
    ::close(from_job[1]);
    input_ = to_job[1];
    output_ = from_job[0];
    REQUIRE(spawned == 0);
  }

  WorkerJob(const WorkerJob&) = delete;
  WorkerJob& operator=(const WorkerJob&) = delete;

  ~WorkerJob() {
    close_stdin();
    if (output_ >= 0) ::close(output_);
    if (!exit_status_) {
      ::kill(-pid_, SIGKILL);
      for (pid_t p : processes_with_marker(marker_)) ::kill(p, SIGKILL);
      int status = 0;
      ::waitpid(pid_, &status, 0);
    }
    std::error_code ignored;
    std::filesystem::remove(stderr_path_, ignored);
  }

  const std::string& marker() const { return marker_; }
  pid_t pid() const { return pid_; }

  void send_line(const std::string& line) {
    const std::string text = line + "\n";
    REQUIRE(::write(input_, text.data(), text.size()) == static_cast<ssize_t>(text.size()));
  }
  void send(const Json& message) { send_line("@aerobreak " + message.dump()); }

  void close_stdin() {
    if (input_ >= 0) ::close(input_);
    input_ = -1;
  }

  // The next protocol message within `timeout` seconds; other lines are kept in other_lines(),
  // heartbeats are counted in heartbeats().
  std::optional<Json> next_message(double timeout) {
    const auto start = Clock::now();
    while (true) {
      const std::size_t end = buffer_.find('\n');
      if (end != std::string::npos) {
        const std::string line = buffer_.substr(0, end);
        buffer_.erase(0, end + 1);
        if (line.rfind("@aerobreak ", 0) == 0) {
          Json message = Json::parse(line.substr(11));
          if (message.value("type", "") != "heartbeat") return message;
          ++heartbeats_;
          continue;
        }
        other_lines_.push_back(line);
        continue;
      }
      const double left = timeout - seconds_since(start);
      if (left <= 0.0) return std::nullopt;
      pollfd waiting{output_, POLLIN, 0};
      if (::poll(&waiting, 1, static_cast<int>(left * 1000.0) + 1) <= 0) continue;
      char chunk[65536];
      const ssize_t got = ::read(output_, chunk, sizeof chunk);
      if (got <= 0) return std::nullopt;
      buffer_.append(chunk, static_cast<std::size_t>(got));
    }
  }

  // The next protocol message, which must come within `timeout` seconds and be of `type`.
  Json expect(const std::string& type, double timeout) {
    const std::optional<Json> message = next_message(timeout);
    INFO("stderr of the job:\n" << stderr_text());
    REQUIRE(message.has_value());
    INFO("message: " << message->dump());
    REQUIRE(message->value("type", "") == type);
    return *message;
  }

  // The exit status of the job if it ends within `timeout` seconds (-1: killed by a signal).
  std::optional<int> wait_exit(double timeout) {
    const auto start = Clock::now();
    while (!exit_status_ && seconds_since(start) < timeout) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_)
        exit_status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      else
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return exit_status_;
  }

  std::string stderr_text() const {
    std::ifstream in(stderr_path_);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  const std::vector<std::string>& other_lines() const { return other_lines_; }
  int heartbeats() const { return heartbeats_; }

 private:
  static std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> result;
    for (std::string& s : strings) result.push_back(s.data());
    result.push_back(nullptr);
    return result;
  }

  std::string marker_;
  std::filesystem::path stderr_path_;
  pid_t pid_ = -1;
  int input_ = -1;
  int output_ = -1;
  std::string buffer_;
  std::vector<std::string> other_lines_;
  int heartbeats_ = 0;
  std::optional<int> exit_status_;
};

}  // namespace aerobreak::testing
