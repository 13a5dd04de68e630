#pragma once
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "engine/io/bounded_input.hpp"
#include "orchestrator/scheduler/scheduler.hpp"
#include "orchestrator/service/connection_stream.hpp"
#include "orchestrator/store/store.hpp"
#include "orchestrator/study/study.hpp"

namespace httplib {
class Server;
}

namespace aerobreak {

struct Endpoints;

struct ServiceOptions {
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port (see Service::port())
  // Required for POST endpoints when `host` is not a loopback address; optional (but then
  // enforced) on loopback.
  std::optional<std::string> token;
  // What one request may ask for: body size, and the study limits (cases, primaries; no cluster
  // files named by a client).
  std::size_t max_body_bytes = kMaxDocumentBytes;  // a request body: a study, as a study file is read
  StudyLimits study_limits = kServiceStudyLimits;
  std::size_t max_page_size = 1000;
  // What one connection may take: connections at once, timeouts, header size (docs/ORCHESTRATOR.md).
  ConnectionLimits connections;
  // Gets one line per request (client, method, target, status, milliseconds); null: no log.
  std::function<void(const std::string&)> access_log;
  // The dashboard's folder (web_assets.hpp): served at `/` with the library files it names; empty:
  // the API only.
  std::filesystem::path web_directory;
  // The folder of the case HDF5 files (STORE.data): GET /api/cases/ID/data serves a case's file only
  // from under it; empty: no such downloads.
  std::filesystem::path data_directory;
};

// The dashboard's folder when --web-dir is not given: the first of these that holds index.html,
//   1. ../share/aerobreak/web beside the running executable's bin/ (an install, cmake/Install.cmake,
//      wherever its prefix was moved),
//   2. the source tree's web/ this binary was built from (a build run in place, build/aerobreak);
// the first when neither does (the service then says it found no page there).
std::filesystem::path default_web_directory();

// True for 127.0.0.0/8, ::1 and "localhost".
bool is_loopback_host(const std::string& host);

// The REST service (schemas/openapi.json) over a store, and a scheduler that it wakes when a study
// arrives (null for a read-only service). The HTTP server runs on threads of its own.
class Service {
 public:
  Service(Store& store, Scheduler* scheduler, ServiceOptions options);
  ~Service();
  Service(const Service&) = delete;
  Service& operator=(const Service&) = delete;

  // Binds the socket (throws std::runtime_error naming the address when it cannot, or when a
  // non-loopback address has no token) and starts serving.
  void start();
  void stop();
  int port() const { return port_; }
  std::string url() const;

 private:
  Store& store_;
  Scheduler* scheduler_;
  ServiceOptions options_;
  std::unique_ptr<Endpoints> endpoints_;  // what the server's handlers answer with: outlives it
  std::unique_ptr<httplib::Server> server_;
  std::thread thread_;
  std::atomic<bool> listening_ended_{false};  // the listening thread has returned
  int port_ = 0;
};

}  // namespace aerobreak
