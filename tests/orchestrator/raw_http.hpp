#pragma once
// Bytes to and from a loopback port for tests that send what an HTTP client library would not
// (malformed, slow, oversized, forged requests). Every wait is bounded.
#include <catch2/catch.hpp>
#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak::testing {

// A TCP connection to 127.0.0.1:port, closed with the object; from `source` (another loopback
// address, e.g. 127.0.0.2: another client to the service) when given.
class RawConnection {
 public:
  explicit RawConnection(int port, const char* source = nullptr) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    REQUIRE(fd_ >= 0);
    if (source) {
      sockaddr_in local{};
      local.sin_family = AF_INET;
      REQUIRE(::inet_pton(AF_INET, source, &local.sin_addr) == 1);
      REQUIRE(::bind(fd_, reinterpret_cast<sockaddr*>(&local), sizeof local) == 0);
    }
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    REQUIRE(::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
  }
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;
  ~RawConnection() { ::close(fd_); }

  // Sends as much of `bytes` as the peer takes; false once it no longer does (it closed).
  bool send(const std::string& bytes) {
    std::size_t sent = 0;
    while (sent < bytes.size()) {
      const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) return false;
      sent += static_cast<std::size_t>(n);
    }
    return true;
  }

  // What the peer sends until it closes the connection or `limit` passes.
  std::string receive_all(std::chrono::milliseconds limit = std::chrono::seconds(10)) {
    std::string received;
    const auto deadline = std::chrono::steady_clock::now() + limit;
    char buffer[65536];
    for (;;) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      pollfd watched{fd_, POLLIN, 0};
      if (left.count() <= 0 || ::poll(&watched, 1, static_cast<int>(left.count())) <= 0) break;
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      received.append(buffer, static_cast<std::size_t>(n));
    }
    return received;
  }

  // Whether the peer has sent something (an answer) or closed the connection.
  bool readable() {
    pollfd watched{fd_, POLLIN, 0};
    return ::poll(&watched, 1, 0) > 0;
  }

  // Whether the peer has closed the connection (a read would return end of file or an error).
  bool closed_by_peer() {
    pollfd watched{fd_, POLLIN, 0};
    if (::poll(&watched, 1, 0) <= 0) return false;
    char byte;
    return ::recv(fd_, &byte, 1, MSG_PEEK | MSG_DONTWAIT) <= 0;
  }

 private:
  int fd_;
};

// Sends a request on a new connection (from `source`, when given) and returns the whole answer.
inline std::string round_trip(int port, const std::string& request, const char* source = nullptr) {
  RawConnection connection(port, source);
  connection.send(request);
  return connection.receive_all();
}

// The status code of an HTTP answer; 0 when there is none.
inline int status_of(const std::string& answer) {
  if (answer.rfind("HTTP/1.1 ", 0) != 0 || answer.size() < 12) return 0;
  return std::stoi(answer.substr(9, 3));
}

// The JSON body of an HTTP answer (discarded when it is not JSON).
inline nlohmann::ordered_json body_of(const std::string& answer) {
  const auto start = answer.find("\r\n\r\n");
  if (start == std::string::npos) return nlohmann::ordered_json::value_t::discarded;
  return nlohmann::ordered_json::parse(answer.substr(start + 4), nullptr, false);
}

// A request with the given method, target, extra header lines (each ending in \r\n) and body.
inline std::string http_request(const std::string& method, const std::string& target, const std::string& headers = {},
                                const std::string& body = {}) {
  std::string request = method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n" + headers;
  if (method == "POST") request += "Content-Length: " + std::to_string(body.size()) + "\r\n";
  return request + "\r\n" + body;
}

}  // namespace aerobreak::testing
