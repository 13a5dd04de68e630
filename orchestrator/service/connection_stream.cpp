#include "orchestrator/service/connection_stream.hpp"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace aerobreak {
namespace {

constexpr auto kStopCheck = std::chrono::milliseconds(100);
// The blank line that ends a header section: CR LF CR LF as the last four bytes.
constexpr unsigned kHeaderEnd = 0x0D0A0D0Au;

std::string seconds_text(std::chrono::milliseconds duration) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", static_cast<double>(duration.count()) / 1000.0);
  return text;
}

void address_of(const sockaddr_storage& address, std::string& ip, int& port) {
  char text[INET6_ADDRSTRLEN] = {};
  if (address.ss_family == AF_INET) {
    const auto& v4 = reinterpret_cast<const sockaddr_in&>(address);
    ::inet_ntop(AF_INET, &v4.sin_addr, text, sizeof text);
    port = ntohs(v4.sin_port);
  } else if (address.ss_family == AF_INET6) {
    const auto& v6 = reinterpret_cast<const sockaddr_in6&>(address);
    ::inet_ntop(AF_INET6, &v6.sin6_addr, text, sizeof text);
    port = ntohs(v6.sin6_port);
  }
  ip = text;
}

}  // namespace

ConnectionLimits health_connection_limits(const ConnectionLimits& limits) {
  ConnectionLimits health = limits;
  health.idle_timeout = std::chrono::seconds(1);
  health.header_timeout = std::chrono::seconds(1);
  health.request_timeout = std::chrono::seconds(5);
  health.requests_per_connection = 1;
  return health;
}

ConnectionStream::ConnectionStream(socket_t socket, const ConnectionLimits& limits,
                                   const std::atomic<socket_t>& listening_socket)
    : socket_(socket), limits_(limits), listening_socket_(listening_socket) {}

bool ConnectionStream::wait_for(short events, Clock::time_point deadline) const {
  for (;;) {
    if (listening_socket_ == INVALID_SOCKET) return false;
    const auto now = Clock::now();
    if (now >= deadline) return false;
    const auto slice = std::min<Clock::duration>(deadline - now, kStopCheck);
    pollfd watched{socket_, events, 0};
    const int ready =
        ::poll(&watched, 1, static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(slice).count()));
    if (ready > 0) return true;
    if (ready < 0 && errno != EINTR) return false;
  }
}

void ConnectionStream::start_awaiting() {
  awaiting_since_ = Clock::now().time_since_epoch().count();
  awaiting_ = true;
}

bool ConnectionStream::await_request() {
  fault_.reset();
  in_headers_ = true;
  header_bytes_ = 0;
  header_lines_ = 0;
  header_line_bytes_ = 0;
  header_tail_ = 0;
  request_bytes_ = 0;
  bytes_written_ = 0;
  start_awaiting();
  if (buffered_begin_ == buffered_end_) {
    if (!wait_for(POLLIN, Clock::now() + limits_.idle_timeout) || !fill_buffer()) return false;
  }
  request_started_ = Clock::now();
  return true;
}

bool ConnectionStream::fill_buffer() {
  for (;;) {
    const ssize_t n = ::recv(socket_, buffer_.data(), buffer_.size(), 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    buffered_begin_ = 0;
    buffered_end_ = static_cast<std::size_t>(n);
    return true;
  }
}

ConnectionStream::Clock::time_point ConnectionStream::read_deadline(bool* by_rate) const {
  const auto timeout = request_started_ + (in_headers_ ? limits_.header_timeout : limits_.request_timeout);
  if (by_rate) *by_rate = false;
  if (limits_.min_bytes_per_second == 0) return timeout;
  const double seconds_earned = static_cast<double>(request_bytes_) / static_cast<double>(limits_.min_bytes_per_second);
  const auto earned = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds_earned));
  const auto by_minimum_rate = request_started_ + limits_.rate_grace + earned;
  if (by_minimum_rate >= timeout) return timeout;
  if (by_rate) *by_rate = true;
  return by_minimum_rate;
}

std::string ConnectionStream::too_slow_message(bool by_rate) const {
  if (by_rate)
    return "the request arrived slower than " + std::to_string(limits_.min_bytes_per_second) + " bytes/s (" +
           std::to_string(request_bytes_) + " bytes in its first " +
           seconds_text(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - request_started_)) + ")";
  return in_headers_ ? "the request line and headers did not arrive within " + seconds_text(limits_.header_timeout)
                     : "the request did not arrive within " + seconds_text(limits_.request_timeout);
}

void ConnectionStream::fail(int status, std::string message) {
  if (!fault_) fault_ = RequestFault{status, std::move(message)};
}

bool ConnectionStream::account_header_bytes(const char* bytes, std::size_t count) {
  for (std::size_t i = 0; i < count && in_headers_; ++i) {
    const auto byte = static_cast<unsigned char>(bytes[i]);
    header_tail_ = (header_tail_ << 8) | byte;
    if (++header_line_bytes_ > limits_.max_header_line_bytes) {
      const bool request_line = header_lines_ == 0;
      fail(request_line ? 414 : 431, std::string(request_line ? "the request line" : "a header line") +
                                         " is longer than " + std::to_string(limits_.max_header_line_bytes) + " bytes");
      return false;
    }
    if (byte == '\n') {
      ++header_lines_;
      header_line_bytes_ = 0;
    }
    if (++header_bytes_ > limits_.max_header_bytes) {
      fail(431, "the request line and headers are longer than " + std::to_string(limits_.max_header_bytes) + " bytes");
      return false;
    }
    if (header_lines_ > limits_.max_header_lines) {
      fail(431, "the request has more than " + std::to_string(limits_.max_header_lines - 1) + " header lines");
      return false;
    }
    if (header_tail_ == kHeaderEnd) {
      in_headers_ = false;
      awaiting_ = false;
    }
  }
  return true;
}

bool ConnectionStream::is_readable() const {
  return buffered_begin_ != buffered_end_ || (!fault_ && wait_for(POLLIN, read_deadline()));
}

ssize_t ConnectionStream::read(char* ptr, size_t size) {
  if (fault_) return -1;
  if (buffered_begin_ == buffered_end_) {
    bool by_rate = false;
    const auto deadline = read_deadline(&by_rate);
    if (!wait_for(POLLIN, deadline)) {
      if (Clock::now() >= deadline) fail(408, too_slow_message(by_rate));
      return -1;
    }
    if (!fill_buffer()) return -1;
  }
  const std::size_t count = std::min(size, buffered_end_ - buffered_begin_);
  const char* bytes = buffer_.data() + buffered_begin_;
  if (in_headers_ && !account_header_bytes(bytes, count)) return -1;
  request_bytes_ += count;
  std::memcpy(ptr, bytes, count);
  buffered_begin_ += count;
  return static_cast<ssize_t>(count);
}

bool ConnectionStream::is_writable() const {
  return wait_for(POLLOUT, std::max(request_started_ + limits_.request_timeout, Clock::now() + limits_.idle_timeout));
}

ssize_t ConnectionStream::write(const char* ptr, size_t size) {
  // A slow reader gets the rest of the request's time, and at least idle_timeout, per write.
  const auto deadline = std::max(request_started_ + limits_.request_timeout, Clock::now() + limits_.idle_timeout);
  std::size_t sent = 0;
  while (sent < size) {
    if (!wait_for(POLLOUT, deadline)) return -1;
    const ssize_t n = ::send(socket_, ptr + sent, size - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;
    if (n <= 0) return -1;
    sent += static_cast<std::size_t>(n);
  }
  bytes_written_ += sent;
  return static_cast<ssize_t>(sent);
}

void ConnectionStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  if (::getpeername(socket_, reinterpret_cast<sockaddr*>(&address), &length) == 0) address_of(address, ip, port);
}

void ConnectionStream::get_local_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  if (::getsockname(socket_, reinterpret_cast<sockaddr*>(&address), &length) == 0) address_of(address, ip, port);
}

}  // namespace aerobreak
