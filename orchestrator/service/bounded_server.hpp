#pragma once
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "orchestrator/service/connection_slots.hpp"
#include "orchestrator/service/connection_stream.hpp"
#include "orchestrator/service/lingering_closes.hpp"

namespace aerobreak {

// cpp-httplib's Server with every connection bounded (ConnectionLimits). Debian's cpp-httplib
// 0.11 gives each connection a fixed pool thread for as long as the client keeps it (a header byte
// every few seconds holds it for good, and idle sockets queue everyone else behind them) and reads
// any number of headers. Here each connection gets a thread of its own once ConnectionSlots
// admits it (per-client shares, slots of connections that await a request given to newcomers,
// slots kept for /api/health; beyond, an immediate 503), and runs its requests through
// ConnectionStream, which ends a request that is too slow (timeouts, minimum rate) or has too
// many header bytes or lines while it arrives.
// It binds without SO_REUSEPORT, so that a port another process listens on is refused.
class BoundedServer : public httplib::Server {
 public:
  // `refusals` gets a line for each connection answered without a request (over the connection
  // limit, or a request line that never completed); null: none.
  BoundedServer(ConnectionLimits limits, std::function<void(const std::string&)> refusals);

  // Once bound: lets the kernel queue as many connections as it allows (SOMAXCONN) while they
  // wait to be accepted. The library listens with a queue of 5, so that a burst of connections
  // (a flood, or a hundred clients at once) had the kernel drop the others' SYNs, and each of
  // those clients waited a second or more to connect.
  void widen_accept_queue();

 private:
  bool process_and_close_socket(socket_t socket) override;
  // Serves the connection's requests; true when it ends with a request refused before it was read
  // whole (bytes the client sent may be unread).
  bool serve_requests(ConnectionStream& stream, bool health_only);
  void answer_directly(socket_t socket, int status, const std::string& message);

  ConnectionLimits limits_;
  ConnectionLimits health_limits_;
  std::function<void(const std::string&)> refusals_;
  ConnectionSlots slots_{limits_};
  LingeringCloses lingering_;
};

// For handlers on a BoundedServer's connection thread (elsewhere they do nothing or return null):
// answer this request with "Connection: close" and close the connection after it (a request refused
// before its body was read must not leave the body to be read as the next request).
void close_connection_after_response(httplib::Response& response);
// Whether the request being answered came on a slot kept for /api/health (ConnectionSlots).
bool current_connection_health_only();
// Why the request being answered could not be read (408, 431), when that is why.
const RequestFault* current_request_fault();
// When the first byte of the request being answered arrived.
std::optional<std::chrono::steady_clock::time_point> current_request_started();

}  // namespace aerobreak
