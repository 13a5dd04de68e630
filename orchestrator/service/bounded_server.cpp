#include "orchestrator/service/bounded_server.hpp"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

namespace aerobreak {
namespace {

// Threads that answer connections beyond max_connections with a 503 (a few microseconds each).
constexpr std::size_t kOverflowThreads = 8;
// A connection closed before its request was read whole (refused early) is drained for this long
// (LingeringCloses), so that the client reads the answer instead of a reset (RFC 9112 9.6).
constexpr auto kLingerTime = std::chrono::seconds(2);

// A thread per connection, started when every thread is busy, up to `max_threads` (then the
// connection waits for one); threads are kept for later connections until shutdown.
class ConnectionThreads final : public httplib::TaskQueue {
 public:
  explicit ConnectionThreads(std::size_t max_threads) : max_threads_(max_threads) {}

  void enqueue(std::function<void()> job) override {
    std::lock_guard lock(mutex_);
    jobs_.push_back(std::move(job));
    if (idle_ < jobs_.size() && threads_.size() < max_threads_) threads_.emplace_back([this] { work(); });
    wake_.notify_one();
  }

  void shutdown() override {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (auto& thread : threads_) thread.join();
  }

 private:
  // Every queued connection is served (a job closes its socket), even while stopping.
  void work() {
    std::unique_lock lock(mutex_);
    for (;;) {
      ++idle_;
      wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
      --idle_;
      if (jobs_.empty()) return;
      auto job = std::move(jobs_.front());
      jobs_.pop_front();
      lock.unlock();
      job();
      lock.lock();
    }
  }

  const std::size_t max_threads_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  std::vector<std::thread> threads_;
  std::size_t idle_ = 0;
  bool stopping_ = false;
};

// SO_REUSEADDR only (a restart may bind while old connections linger in TIME_WAIT); cpp-httplib's
// default adds SO_REUSEPORT, with which a second service binds a port that one already listens on.
void reuse_address_only(socket_t socket) {
  int yes = 1;
  ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
}

const char* reason_phrase(int status) {
  switch (status) {
    case 408:
      return "Request Timeout";
    case 414:
      return "URI Too Long";
    case 431:
      return "Request Header Fields Too Large";
    case 503:
      return "Service Unavailable";
    default:
      return "Error";
  }
}

// The library answers Range with as many parts as asked (1,500 "0-" parts made a 47-byte file
// 201 KB) and 206 even for an unsatisfiable one on a streamed answer: its ranges are dropped here,
// and the service's post-routing handler answers Range instead (byte_ranges.hpp).
void leave_ranges_to_handlers(httplib::Request& request) { request.ranges.clear(); }

struct CurrentConnection {
  ConnectionStream* stream = nullptr;
  bool health_only = false;
  bool close_after_response = false;
};

std::string client_address(socket_t socket) {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  char text[INET6_ADDRSTRLEN] = {};
  if (::getpeername(socket, reinterpret_cast<sockaddr*>(&address), &length) != 0) return {};
  if (address.ss_family == AF_INET)
    ::inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in&>(address).sin_addr, text, sizeof text);
  else if (address.ss_family == AF_INET6)
    ::inet_ntop(AF_INET6, &reinterpret_cast<const sockaddr_in6&>(address).sin6_addr, text, sizeof text);
  return text;
}

thread_local CurrentConnection* current_connection = nullptr;

}  // namespace

BoundedServer::BoundedServer(ConnectionLimits limits, std::function<void(const std::string&)> refusals)
    : limits_(limits), health_limits_(health_connection_limits(limits)), refusals_(std::move(refusals)) {
  // The connections a newcomer's slot was taken from are still ending when it starts.
  const std::size_t threads = 2 * (limits_.max_connections + limits_.health_connections) + kOverflowThreads;
  new_task_queue = [threads] { return new ConnectionThreads(threads); };
  set_socket_options(reuse_address_only);
  // What the library advertises in Keep-Alive headers; the loop below enforces it.
  set_keep_alive_max_count(limits_.requests_per_connection);
  set_keep_alive_timeout(std::chrono::duration_cast<std::chrono::seconds>(limits_.idle_timeout).count());
}

void BoundedServer::widen_accept_queue() {
  if (svr_sock_ != INVALID_SOCKET) ::listen(svr_sock_, SOMAXCONN);
}

bool BoundedServer::process_and_close_socket(socket_t socket) {
  std::size_t closed = 0;
  const auto ticket = slots_.admit(client_address(socket), closed);
  if (closed > 0 && refusals_)
    refusals_("- closed a connection that awaited its request, for a new one: every slot was taken");
  if (ticket.kind == ConnectionSlots::Kind::refused) {
    answer_directly(socket, 503,
                    "the service is serving its limit of " + std::to_string(limits_.max_connections) +
                        " connections; try again shortly");
    lingering_.close(socket, std::chrono::milliseconds(0));
    return true;
  }
  const bool health_only = ticket.kind == ConnectionSlots::Kind::health;
  bool refused_unread = false;
  {
    ConnectionStream stream(socket, health_only ? health_limits_ : limits_, svr_sock_);
    slots_.attach(ticket, stream);
    refused_unread = serve_requests(stream, health_only);
    // Before the stream ends: a newcomer looks at the streams of the slots it may take.
    slots_.release(ticket);
  }
  if (refused_unread) {
    lingering_.close(socket, kLingerTime);
  } else {
    ::shutdown(socket, SHUT_RDWR);
    ::close(socket);
  }
  return true;
}

bool BoundedServer::serve_requests(ConnectionStream& stream, bool health_only) {
  const ConnectionLimits& limits = health_only ? health_limits_ : limits_;
  CurrentConnection connection{&stream, health_only};
  current_connection = &connection;
  for (std::size_t served = 0; served < limits.requests_per_connection && stream.await_request(); ++served) {
    bool client_closes = false;
    const bool last = served + 1 == limits.requests_per_connection;
    const bool answered = process_request(stream, last, client_closes, leave_ranges_to_handlers);
    // A request line that never completed leaves the library nothing to answer.
    if (stream.fault() && stream.bytes_written() == 0)
      answer_directly(stream.socket(), stream.fault()->status, stream.fault()->message);
    if (!answered || client_closes || connection.close_after_response || stream.fault()) break;
  }
  current_connection = nullptr;
  return connection.close_after_response || stream.fault();
}

void BoundedServer::answer_directly(socket_t socket, int status, const std::string& message) {
  const std::string body = nlohmann::json{{"error", message}, {"violations", nlohmann::json::array()}}.dump();
  const std::string answer = "HTTP/1.1 " + std::to_string(status) + " " + reason_phrase(status) +
                             "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) +
                             "\r\nConnection: close\r\n\r\n" + body;
  // One non-blocking send: a client that does not read its answer gets none.
  ::send(socket, answer.data(), answer.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  if (refusals_) refusals_("- " + std::to_string(status) + " " + message);
}

void close_connection_after_response(httplib::Response& response) {
  response.set_header("Connection", "close");
  if (current_connection) current_connection->close_after_response = true;
}

bool current_connection_health_only() { return current_connection && current_connection->health_only; }

const RequestFault* current_request_fault() {
  if (!current_connection || !current_connection->stream->fault()) return nullptr;
  return &*current_connection->stream->fault();
}

std::optional<std::chrono::steady_clock::time_point> current_request_started() {
  if (!current_connection) return std::nullopt;
  return current_connection->stream->request_started();
}

}  // namespace aerobreak
