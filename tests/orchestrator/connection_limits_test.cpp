// Connections that hold on (slow-loris, slow bodies, idle sockets, too many at once) cannot keep the
// service from answering, and a port another service listens on is refused (docs/ORCHESTRATOR.md,
// "Limits" and "What happens when things fail").
// Real `aerobreak serve`, real sockets, loopback only (other clients from 127.0.0.2 and up, which
// Linux routes over loopback too); every wait is bounded.
#include <cstdio>
#include <memory>
#include <vector>

#include "tests/orchestrator/raw_http.hpp"
#include "tests/orchestrator/service_process.hpp"
#include "tests/support/run_command.hpp"

namespace aerobreak::testing {
namespace {

bool health_answers(int port) {
  httplib::Client client("127.0.0.1", port);
  client.set_connection_timeout(2, 0);
  client.set_read_timeout(2, 0);
  const auto response = client.Get("/api/health");
  return response && response->status == 200;
}

std::vector<std::unique_ptr<RawConnection>> open_connections(int port, int count, const char* source = nullptr) {
  std::vector<std::unique_ptr<RawConnection>> connections;
  for (int i = 0; i < count; ++i) connections.push_back(std::make_unique<RawConnection>(port, source));
  return connections;
}

// Headers of a POST whose body (of `length` bytes) has not been sent.
std::string slow_body_headers(std::size_t length = 100000) {
  return "POST /api/studies HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\nContent-Length: " +
         std::to_string(length) + "\r\n\r\n{";
}

// One connection of a slow-sender load: it sends a byte a second (of a header section, or of a
// body after whole headers) and, cut off, connects again.
struct SlowSender {
  bool body = false;
  std::unique_ptr<RawConnection> connection;
  int reconnects = 0;

  void start(int port) {
    connection = std::make_unique<RawConnection>(port);
    connection->send(body ? slow_body_headers() : "G");
  }
  void drip(int port) {
    if (connection->readable()) {  // answered (408, 503) or closed: connect again
      ++reconnects;
      start(port);
      return;
    }
    connection->send(body ? "1" : "E");
  }
};

}  // namespace

TEST_CASE("Health answers while 8 connections dribble headers and 24 sockets sit idle, and both are cut off",
          "[service][hostile]") {
  ScratchDirectory scratch("slow-loris");
  ServiceProcess service(scratch.path());
  const int port = service.port();
  auto slow = open_connections(port, 8, "127.0.0.2");
  for (auto& connection : slow) connection->send("GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n");
  auto idle = open_connections(port, 24, "127.0.0.2");

  // A header byte every 2 s on each slow connection for 12 s (past the minimum rate after 2 s, and
  // the 10 s allowed for a header section), health asked every half second meanwhile.
  const auto start = std::chrono::steady_clock::now();
  auto next_byte = start;
  int asked = 0, answered = 0;
  while (std::chrono::steady_clock::now() - start < 12s) {
    if (std::chrono::steady_clock::now() >= next_byte) {
      for (auto& connection : slow)
        if (!connection->readable()) connection->send("X");
      next_byte += 2s;
    }
    ++asked;
    answered += health_answers(port);
    std::this_thread::sleep_for(500ms);
  }
  CHECK(asked >= 20);
  CHECK(answered == asked);
  for (auto& connection : slow) {
    const std::string answer = connection->receive_all(2s);
    CHECK(status_of(answer) == 408);
    CHECK_THAT(body_of(answer).at("error").get<std::string>(), Catch::Contains("slower than 512 bytes/s"));
  }
  for (auto& connection : idle) CHECK(connection->closed_by_peer());
}

TEST_CASE("80 sockets dripping headers and 70 dripping bodies, reconnecting, starve neither health nor other clients",
          "[service][hostile]") {
  ScratchDirectory scratch("slow-senders");
  ServiceProcess service(scratch.path(), {"--quiet"});
  const int port = service.port();
  // All from 127.0.0.1, as the health checks: one client holding every connection it can.
  std::vector<SlowSender> senders(150);
  for (std::size_t i = 0; i < senders.size(); ++i) {
    senders[i].body = i >= 80;
    senders[i].start(port);
  }
  const auto start = std::chrono::steady_clock::now();
  auto next_drip = start;
  int health_asked = 0, health_answered = 0, other_asked = 0, other_answered = 0;
  while (std::chrono::steady_clock::now() - start < 14s) {
    if (std::chrono::steady_clock::now() >= next_drip) {
      for (auto& sender : senders) sender.drip(port);
      next_drip += 1s;
    }
    if (std::chrono::steady_clock::now() - start < 2s) {  // the load builds up first
      std::this_thread::sleep_for(100ms);
      continue;
    }
    ++health_asked;
    health_answered += health_answers(port);
    if (health_asked % 4 == 0) {
      ++other_asked;
      other_answered += status_of(round_trip(port, http_request("GET", "/api/studies"), "127.0.0.3")) == 200;
    }
    std::this_thread::sleep_for(250ms);
  }
  int reconnects = 0;
  for (const auto& sender : senders) reconnects += sender.reconnects;
  std::printf(
      "slow senders: health answered %d of %d, another client %d of %d; senders cut off and reconnected %d "
      "times\n",
      health_answered, health_asked, other_answered, other_asked, reconnects);
  CHECK(health_asked >= 40);
  CHECK(health_answered == health_asked);
  CHECK(other_answered == other_asked);
  // The minimum rate cut every sender off within a few seconds, again and again.
  CHECK(reconnects > 300);
}

TEST_CASE(
    "Past --max-connections a newcomer takes the slot of a connection awaiting its request, health keeps slots "
    "of its own, and the rest get an immediate 503",
    "[service][hostile]") {
  ScratchDirectory scratch("max-connections");
  ServiceProcess service(scratch.path(), {"--max-connections", "4"});
  {
    // Idle connections of two clients fill the four slots; a third client is served in one's place.
    auto idle = open_connections(service.port(), 2, "127.0.0.2");
    auto more = open_connections(service.port(), 2, "127.0.0.3");
    std::this_thread::sleep_for(200ms);
    CHECK(status_of(round_trip(service.port(), http_request("GET", "/api/studies"), "127.0.0.4")) == 200);
    int closed = 0;
    for (auto* group : {&idle, &more})
      for (auto& connection : *group) closed += connection->closed_by_peer();
    CHECK(closed == 1);
  }
  {
    // Four requests being read (whole headers, bodies coming) hold every slot: not to be taken.
    auto held = open_connections(service.port(), 2, "127.0.0.2");
    auto more = open_connections(service.port(), 2, "127.0.0.3");
    for (auto* group : {&held, &more})
      for (auto& connection : *group) connection->send(slow_body_headers());
    std::this_thread::sleep_for(200ms);
    const auto asked = std::chrono::steady_clock::now();
    const std::string refused = round_trip(service.port(), http_request("GET", "/api/studies"), "127.0.0.4");
    CHECK(std::chrono::steady_clock::now() - asked < 1s);
    CHECK(status_of(refused) == 503);
    CHECK_THAT(body_of(refused).at("error").get<std::string>(),
               Catch::Contains("limit of 4 connections") && Catch::Contains("only GET /api/health"));
    CHECK(status_of(round_trip(service.port(), http_request("GET", "/api/health"), "127.0.0.4")) == 200);
    // Bodies that do not come at the minimum rate are cut off with 408.
    for (auto& connection : held) {
      const std::string answer = connection->receive_all(5s);
      CHECK(status_of(answer) == 408);
    }
  }
  CHECK(eventually([&] { return health_answers(service.port()); }, 5s));
}

TEST_CASE("A port another service listens on is refused: serve stops, run moves to a free port", "[service][hostile]") {
  ScratchDirectory scratch("port-taken");
  ServiceProcess first(scratch.path());
  const std::string port = std::to_string(first.port());
  // `timeout`: before the fix the second service would run on for good.
  const auto second = run_command("timeout 20 " + std::string(AEROBREAK_BINARY) + " serve --port " + port +
                                  " --store " + scratch.file("second.sqlite"));
  CHECK(second.exit_code == 1);
  CHECK_THAT(second.text, Catch::Contains("cannot listen on 127.0.0.1:" + port));

  const auto study = scratch.write("tiny.study.json", small_study("tiny", {0.01}, 1).dump());
  const auto run = run_command("timeout 120 " + std::string(AEROBREAK_BINARY) + " run " + study.string() +
                               " --ranks 1 --port " + port + " --store " + scratch.file("run.sqlite"));
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.text, Catch::Contains("port " + port + " is taken; serving on a free port instead"));
  CHECK(health_answers(first.port()));
}

}  // namespace aerobreak::testing
