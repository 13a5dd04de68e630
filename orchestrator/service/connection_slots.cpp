#include "orchestrator/service/connection_slots.hpp"

#include <sys/socket.h>

#include <algorithm>

namespace aerobreak {

void ConnectionSlots::count(const Holder& holder, bool taken) {
  if (holder.kind == Kind::health) {
    taken ? ++health_ : --health_;
    return;
  }
  taken ? ++regular_ : --regular_;
  auto& held = per_client_[holder.client];
  taken ? ++held : --held;
  if (held == 0) per_client_.erase(holder.client);
}

ConnectionSlots::Ticket ConnectionSlots::take(const std::string& client, Kind kind) {
  holders_.push_back({next_id_++, client, kind});
  count(holders_.back(), true);
  return {kind, holders_.back().id};
}

bool ConnectionSlots::close_longest_waiting(Kind kind, const std::string& client) {
  Holder* longest = nullptr;
  for (auto& holder : holders_) {
    if (holder.kind != kind || holder.closed || !holder.stream || !holder.stream->awaiting_request()) continue;
    if (!client.empty() && holder.client != client) continue;
    if (!longest || holder.stream->awaiting_since() < longest->stream->awaiting_since()) longest = &holder;
  }
  if (!longest) return false;
  // Its thread sees the end of the connection at once; the socket stays open until release().
  ::shutdown(longest->stream->socket(), SHUT_RDWR);
  longest->closed = true;
  count(*longest, false);
  return true;
}

ConnectionSlots::Ticket ConnectionSlots::admit(const std::string& client, std::size_t& closed) {
  std::unique_lock lock(mutex_);
  closed = 0;
  const auto deadline = std::chrono::steady_clock::now() + kWaitForSlot;
  for (;;) {
    const Ticket ticket = try_admit(client, closed);
    if (ticket.kind != Kind::refused) return ticket;
    if (freed_.wait_until(lock, deadline) == std::cv_status::timeout) return try_admit(client, closed);
  }
}

ConnectionSlots::Ticket ConnectionSlots::try_admit(const std::string& client, std::size_t& closed) {
  const auto held = per_client_.find(client);
  const bool client_full = held != per_client_.end() && held->second >= limits_.max_connections_per_client;
  if (client_full) {
    if (close_longest_waiting(Kind::regular, client)) return ++closed, take(client, Kind::regular);
  } else if (regular_ < limits_.max_connections) {
    return take(client, Kind::regular);
  } else if (close_longest_waiting(Kind::regular, {})) {
    return ++closed, take(client, Kind::regular);
  }
  if (health_ < limits_.health_connections) return take(client, Kind::health);
  if (close_longest_waiting(Kind::health, {})) return ++closed, take(client, Kind::health);
  return {};
}

void ConnectionSlots::attach(const Ticket& ticket, const ConnectionStream& stream) {
  std::lock_guard lock(mutex_);
  for (auto& holder : holders_)
    if (holder.id == ticket.id) holder.stream = &stream;
}

void ConnectionSlots::release(const Ticket& ticket) {
  std::lock_guard lock(mutex_);
  const auto found = std::find_if(holders_.begin(), holders_.end(), [&](const Holder& h) { return h.id == ticket.id; });
  if (found == holders_.end()) return;
  if (!found->closed) count(*found, false);
  holders_.erase(found);
  freed_.notify_all();
}

}  // namespace aerobreak
