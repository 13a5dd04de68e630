#pragma once
// `aerobreak serve` as a real process for the service tests: started on a free loopback port with
// its own store in a fresh temporary directory, reached over real HTTP, stopped or killed by the
// test. Every wait is bounded.
#include <catch2/catch.hpp>
#include <httplib.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {

using Json = nlohmann::ordered_json;
using namespace std::chrono_literals;

// Polls `done` every 100 ms until it holds or `limit` passes; returns whether it held.
inline bool eventually(const std::function<bool()>& done, std::chrono::milliseconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(100ms);
  }
  return done();
}

inline bool process_alive(pid_t pid) { return pid > 0 && ::kill(pid, 0) == 0; }

class ServiceProcess {
 public:
  // The store is DIRECTORY/store.sqlite unless `store_file` names another; `program` is the
  // aerobreak that serves (an installed one, say).
  ServiceProcess(const std::filesystem::path& directory, std::vector<std::string> extra_arguments = {},
                 std::filesystem::path store_file = {}, const std::string& program = AEROBREAK_BINARY)
      : directory_(directory), store_file_(store_file.empty() ? directory / "store.sqlite" : store_file) {
    const auto port_file = directory_ / "port";
    std::filesystem::remove(port_file);
    std::vector<std::string> arguments{program, "serve",       "--store",          store_file_.string(), "--port",
                                       "0",     "--port-file", port_file.string(), "--idle-shutdown",    "1"};
    // Two ranks unless the test chooses (an option may be given once).
    if (std::find(extra_arguments.begin(), extra_arguments.end(), "--ranks") == extra_arguments.end())
      arguments.insert(arguments.end(), {"--ranks", "2"});
    arguments.insert(arguments.end(), extra_arguments.begin(), extra_arguments.end());
    const auto log = directory_ / "serve.log";
    pid_ = ::fork();
    REQUIRE(pid_ >= 0);
    if (pid_ == 0) {
      std::vector<char*> argv;
      for (auto& word : arguments) argv.push_back(word.data());
      argv.push_back(nullptr);
      std::FILE* out = std::fopen(log.c_str(), "a");
      ::dup2(::fileno(out), STDERR_FILENO);
      ::dup2(::fileno(out), STDOUT_FILENO);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    REQUIRE(eventually([&] { return std::filesystem::exists(port_file) || exited(); }, 30s));
    REQUIRE_FALSE(exited());
    std::ifstream(port_file) >> port_;
    REQUIRE(port_ > 0);
  }
  ServiceProcess(const ServiceProcess&) = delete;
  ServiceProcess& operator=(const ServiceProcess&) = delete;
  ~ServiceProcess() { kill(SIGKILL); }

  pid_t pid() const { return pid_; }
  int port() const { return port_; }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  const std::filesystem::path& store_file() const { return store_file_; }
  std::string log() const {
    std::ifstream in(directory_ / "serve.log");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  httplib::Client client() const {
    httplib::Client client("127.0.0.1", port_);
    client.set_connection_timeout(5, 0);
    client.set_read_timeout(30, 0);
    return client;
  }

  Json get(const std::string& path) const {
    auto client = this->client();
    const auto response = client.Get(path.c_str());
    REQUIRE(response);
    INFO(path << " -> " << response->status << " " << response->body);
    REQUIRE(response->status == 200);
    return Json::parse(response->body);
  }

  // Sends a signal and waits (bounded) for the process to end; returns its exit code, or 128 + signal.
  int kill(int signal) {
    if (pid_ <= 0) return exit_code_;
    ::kill(pid_, signal);
    for (int i = 0; i < 300 && !exited(); ++i) std::this_thread::sleep_for(100ms);
    if (!exited()) {
      ::kill(pid_, SIGKILL);
      int status = 0;
      ::waitpid(pid_, &status, 0);
      record(status);
    }
    return exit_code_;
  }

 private:
  bool exited() {
    if (pid_ <= 0) return true;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
    record(status);
    return true;
  }
  void record(int status) {
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    pid_ = -1;
  }

  std::filesystem::path directory_;
  std::filesystem::path store_file_;
  pid_t pid_ = -1;
  int port_ = 0;
  int exit_code_ = -1;
};

// A study of ballistic clusters hitting an adhesive wall, small enough for tests:
// speeds x replicates cases of `primaries` primaries.
inline Json small_study(const std::string& name, Json speeds, int replicates, int primaries = 16,
                        double time_limit = 20000.0) {
  return {{"name", name},
          {"base",
           {{"cluster", {{"generator", {{"method", "ballistic"}, {"primaries", primaries}}}}},
            {"material", {{"gamma_over_kn", 0.001}}},
            {"model", {{"damping", {{"law", "viscoelastic"}, {"dissipative_time", 0.05}}}}},
            {"run", {{"time_limit", time_limit}}}}},
          {"axes", {{"impact_speed", {{"values", speeds}}}}},
          {"replicates", {{"count", replicates}, {"seed", 7}}},
          {"execution", {{"max_attempts", 3}, {"case_wall_time", 600}}}};
}

// Cases of ~0.3-1 s each on one core: slow enough to kill something, or fill a disk, mid-study.
inline Json slow_study(const std::string& name, int cases) {
  Json speeds = Json::array();
  for (int i = 0; i < cases; ++i) speeds.push_back(0.004 + 0.001 * i);
  return small_study(name, speeds, 1, 128, 40000.0);
}

// POST /api/studies, with `query` ("?recompute_data_files=true") when given.
inline Json submit(const ServiceProcess& service, const Json& study, int expected_status = 201,
                   const std::string& query = {}) {
  auto client = service.client();
  const auto response = client.Post(("/api/studies" + query).c_str(), study.dump(), "application/json");
  REQUIRE(response);
  INFO(response->body);
  REQUIRE(response->status == expected_status);
  return Json::parse(response->body);
}

inline bool study_complete(const ServiceProcess& service, std::int64_t study) {
  return service.get("/api/studies/" + std::to_string(study) + "/progress").at("complete").get<bool>();
}

}  // namespace aerobreak::testing
