#pragma once
#include <httplib.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

namespace aerobreak {

// What one connection may take from the service (docs/ORCHESTRATOR.md, "Limits").
struct ConnectionLimits {
  std::size_t max_connections = 64;             // served at once (connection_slots.hpp)
  std::size_t max_connections_per_client = 32;  // of them held by one client address
  std::size_t health_connections = 4;           // beyond max_connections, for GET and HEAD /api/health only
  std::chrono::milliseconds idle_timeout{std::chrono::seconds(5)};      // before a request's first byte
  std::chrono::milliseconds header_timeout{std::chrono::seconds(10)};   // first byte to end of headers
  std::chrono::milliseconds request_timeout{std::chrono::seconds(30)};  // first byte to end of answer
  // A request's bytes (headers and body) must arrive at min_bytes_per_second on average from its
  // first byte once its first rate_grace has passed: by first byte + rate_grace + bytes / rate.
  std::size_t min_bytes_per_second = 512;
  std::chrono::milliseconds rate_grace{std::chrono::seconds(2)};
  std::size_t max_header_bytes = 32 * 1024;  // request line and headers
  std::size_t max_header_lines = 100;        // request line and headers
  // One line, its line end included: cpp-httplib's own limit (CPPHTTPLIB_HEADER_MAX_LENGTH), past
  // which it answered a bare 400 and read the rest of the line as further requests.
  std::size_t max_header_line_bytes = 8192;
  std::size_t requests_per_connection = 100;  // keep-alive
};

// The limits of a connection on one of the slots kept for /api/health: one request, whole within
// a second of the connection (a health check sends it at once).
ConnectionLimits health_connection_limits(const ConnectionLimits& limits);

// Why a request could not be read: the status to answer with and the message.
struct RequestFault {
  int status;
  std::string message;
};

// One accepted connection as cpp-httplib's Stream, with the limits above enforced as the bytes
// arrive rather than after the library has buffered them: a request's header section must end
// within max_header_bytes, max_header_lines and header_timeout of its first byte, the rest of the
// request and its answer within request_timeout, and its bytes arrive at the minimum rate;
// otherwise reading fails and fault() says why. Every wait also ends within 100 ms of the server
// closing its listening socket (it stops). Whether it waits for a request (before its first byte,
// or while its header section arrives) and since when can be read from any thread: a connection
// slot can be given to a newcomer (connection_slots.hpp).
class ConnectionStream final : public httplib::Stream {
 public:
  using Clock = std::chrono::steady_clock;

  ConnectionStream(socket_t socket, const ConnectionLimits& limits, const std::atomic<socket_t>& listening_socket);

  // Waits at most idle_timeout for the next request's first byte; false when none came, the peer
  // closed, or the server stops. Then starts that request's budget.
  bool await_request();
  const std::optional<RequestFault>& fault() const { return fault_; }
  // True from the end of an answer (or the connection's start) until a request's header section
  // has arrived whole.
  bool awaiting_request() const { return awaiting_; }
  Clock::time_point awaiting_since() const { return Clock::time_point(Clock::duration(awaiting_since_)); }
  Clock::time_point request_started() const { return request_started_; }
  std::size_t bytes_written() const { return bytes_written_; }

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  socket_t socket() const override { return socket_; }

 private:
  // Waits for `events` on the socket until `deadline`; false on timeout, error or stop.
  bool wait_for(short events, Clock::time_point deadline) const;
  bool fill_buffer();
  // Counts header bytes and lines handed to the library; false (with a fault) past a limit.
  bool account_header_bytes(const char* bytes, std::size_t count);
  // The time by which more of the request must have arrived; `by_rate` tells whether the minimum
  // rate, not a timeout, sets it.
  Clock::time_point read_deadline(bool* by_rate = nullptr) const;
  void start_awaiting();
  std::string too_slow_message(bool by_rate) const;
  void fail(int status, std::string message);

  socket_t socket_;
  const ConnectionLimits& limits_;
  const std::atomic<socket_t>& listening_socket_;
  std::array<char, 4096> buffer_{};
  std::size_t buffered_begin_ = 0;
  std::size_t buffered_end_ = 0;
  bool in_headers_ = true;
  std::size_t header_bytes_ = 0;
  std::size_t header_lines_ = 0;
  std::size_t header_line_bytes_ = 0;  // of the line arriving, so far
  unsigned header_tail_ = 0;           // the last bytes of the header section, to spot its blank line
  std::size_t request_bytes_ = 0;      // of the current request, handed to the library so far
  std::atomic<bool> awaiting_{true};
  std::atomic<Clock::rep> awaiting_since_{Clock::now().time_since_epoch().count()};
  Clock::time_point request_started_{};
  std::size_t bytes_written_ = 0;
  std::optional<RequestFault> fault_;
};

}  // namespace aerobreak
