#include "orchestrator/service/service.hpp"

#include <httplib.h>
#include <arpa/inet.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "orchestrator/scheduler/launcher.hpp"
#include "orchestrator/service/bounded_server.hpp"
#include "orchestrator/service/endpoints.hpp"
#include "orchestrator/service/http_api.hpp"

namespace aerobreak {

bool is_loopback_host(const std::string& host) {
  if (host == "localhost" || host == "::1") return true;
  in_addr address{};
  return ::inet_pton(AF_INET, host.c_str(), &address) == 1 && (ntohl(address.s_addr) >> 24) == 127;
}

std::filesystem::path default_web_directory() {
  const std::filesystem::path installed =
      (current_executable().parent_path() / AEROBREAK_INSTALLED_WEB_DIR).lexically_normal();
  for (const auto& folder : {installed, std::filesystem::path(AEROBREAK_WEB_DIR)})
    if (std::filesystem::is_regular_file(folder / "index.html")) return folder;
  return installed;  // where a page was looked for first, for the message that there is none
}

Service::Service(Store& store, Scheduler* scheduler, ServiceOptions options)
    : store_(store), scheduler_(scheduler), options_(std::move(options)) {}

Service::~Service() { stop(); }

void Service::start() {
  if (!is_loopback_host(options_.host) && !options_.token)
    throw std::runtime_error("refusing to listen on " + options_.host +
                             " without a bearer token: give --token-file (or listen on 127.0.0.1)");
  auto server = std::make_unique<BoundedServer>(options_.connections, options_.access_log);
  BoundedServer& bounded = *server;
  server_ = std::move(server);
  server_->set_payload_max_length(options_.max_body_bytes);
  // Small JSON answers: without TCP_NODELAY, Nagle's algorithm and delayed ACKs add ~40 ms to each.
  server_->set_tcp_nodelay(true);
  endpoints_ = std::make_unique<Endpoints>(store_, scheduler_, options_);
  register_http_api(*server_, *endpoints_);
  errno = 0;
  port_ = options_.port == 0 ? server_->bind_to_any_port(options_.host)
                             : (server_->bind_to_port(options_.host, options_.port) ? options_.port : -1);
  if (port_ <= 0) {
    const std::string reason = errno != 0 ? std::strerror(errno) : "the address is not available";
    throw std::runtime_error("cannot listen on " + options_.host + ":" + std::to_string(options_.port) + ": " + reason +
                             " (another service on that port? choose another with --port)");
  }
  bounded.widen_accept_queue();
  listening_ended_ = false;
  thread_ = std::thread([this] {
    server_->listen_after_bind();
    listening_ended_ = true;
  });
  // cpp-httplib's stop() does nothing to a server whose thread has not yet begun to listen, and
  // that thread would then wait in accept() for good (seen: `aerobreak run` finishing a study
  // within milliseconds hung at exit). Return once it listens, or has already given up.
  while (!server_->is_running() && !listening_ended_) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void Service::stop() {
  if (server_) server_->stop();
  if (thread_.joinable()) thread_.join();
}

std::string Service::url() const {
  const std::string host = options_.host.find(':') != std::string::npos ? "[" + options_.host + "]" : options_.host;
  return "http://" + host + ":" + std::to_string(port_);
}

}  // namespace aerobreak
