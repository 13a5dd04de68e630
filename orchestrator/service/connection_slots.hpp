#pragma once
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "orchestrator/service/connection_stream.hpp"

namespace aerobreak {

// Who holds the service's connections (docs/ORCHESTRATOR.md, "Limits"), so that slow or idle
// clients cannot starve the others nor /api/health:
//  - max_connections regular slots, of which one client address holds at most
//    max_connections_per_client;
//  - where no regular slot is free to a newcomer (all taken, or its address holds its share), the
//    slot of the connection that has waited longest for a request (idle, or its header section
//    still arriving: nothing of it is being served) is given to the newcomer, that connection
//    closed; first among the newcomer's own, then among all;
//  - where every slot holds a request being served, one of health_connections more slots, whose
//    connection may ask only for GET or HEAD /api/health (health_connection_limits);
//  - beyond those, the newcomer waits up to kWaitForSlot for a slot to be given back (a health
//    slot is held for the milliseconds of one short answer), then is refused (503 at once).
class ConnectionSlots {
 public:
  static constexpr std::chrono::milliseconds kWaitForSlot{250};

  enum class Kind { regular, health, refused };
  struct Ticket {
    Kind kind = Kind::refused;
    std::size_t id = 0;
  };

  explicit ConnectionSlots(const ConnectionLimits& limits) : limits_(limits) {}

  // Takes a slot for a new connection from `client`; `closed` counts the connections closed for it.
  Ticket admit(const std::string& client, std::size_t& closed);
  // Makes the ticket's connection one that a newcomer may close while it awaits a request.
  void attach(const Ticket& ticket, const ConnectionStream& stream);
  // Gives the slot back, before the stream attached ends and the connection's socket is closed
  // (a refused ticket holds none).
  void release(const Ticket& ticket);

 private:
  struct Holder {
    std::size_t id;
    std::string client;
    Kind kind;
    const ConnectionStream* stream = nullptr;
    bool closed = false;  // its slot went to a newcomer
  };

  // Closes the connection of `kind` (of `client`, unless empty) that has awaited a request longest,
  // freeing its slot; false when none awaits one.
  bool close_longest_waiting(Kind kind, const std::string& client);
  void count(const Holder& holder, bool taken);
  Ticket take(const std::string& client, Kind kind);
  Ticket try_admit(const std::string& client, std::size_t& closed);

  const ConnectionLimits& limits_;
  std::mutex mutex_;
  std::condition_variable freed_;  // a slot was given back
  std::vector<Holder> holders_;    // at most max_connections + health_connections: scanned, not indexed
  std::unordered_map<std::string, std::size_t> per_client_;  // regular slots by client address
  std::size_t regular_ = 0;
  std::size_t health_ = 0;
  std::size_t next_id_ = 0;
};

}  // namespace aerobreak
