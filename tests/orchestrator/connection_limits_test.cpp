// Connections that hold on (slow-loris, idle sockets, too many at once) cannot keep the service
// from answering, and a port another service listens on is refused (docs/ORCHESTRATOR.md, "Limits"
// and "What happens when things fail"). Real
// `aerobreak serve`, real sockets, loopback only; every wait is bounded.
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

std::vector<std::unique_ptr<RawConnection>> open_connections(int port, int count) {
  std::vector<std::unique_ptr<RawConnection>> connections;
  for (int i = 0; i < count; ++i) connections.push_back(std::make_unique<RawConnection>(port));
  return connections;
}

}  // namespace

TEST_CASE("Health answers while 8 connections dribble headers and 24 sockets sit idle, and both are cut off",
          "[service][hostile]") {
  ScratchDirectory scratch("slow-loris");
  ServiceProcess service(scratch.path());
  const int port = service.port();
  auto slow = open_connections(port, 8);
  for (auto& connection : slow) connection->send("GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n");
  auto idle = open_connections(port, 24);

  // A header byte every 2 s on each slow connection for 12 s (past the 10 s allowed for a header
  // section), health asked every half second meanwhile.
  const auto start = std::chrono::steady_clock::now();
  auto next_byte = start;
  int asked = 0, answered = 0;
  while (std::chrono::steady_clock::now() - start < 12s) {
    if (std::chrono::steady_clock::now() >= next_byte) {
      for (auto& connection : slow)
        if (!connection->closed_by_peer()) connection->send("X");
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
  }
  for (auto& connection : idle) CHECK(connection->closed_by_peer());
}

TEST_CASE("Connections beyond --max-connections get an immediate 503, and the service recovers",
          "[service][hostile]") {
  ScratchDirectory scratch("max-connections");
  ServiceProcess service(scratch.path(), {"--max-connections", "4"});
  {
    auto held = open_connections(service.port(), 4);
    std::this_thread::sleep_for(200ms);  // all four taken up by the server
    RawConnection extra(service.port());
    const auto asked = std::chrono::steady_clock::now();
    extra.send(http_request("GET", "/api/health"));
    const std::string answer = extra.receive_all(3s);
    CHECK(std::chrono::steady_clock::now() - asked < 1s);
    CHECK(status_of(answer) == 503);
    CHECK_THAT(body_of(answer).at("error").get<std::string>(), Catch::Contains("limit of 4 connections"));
  }
  CHECK(eventually([&] { return health_answers(service.port()); }, 5s));
}

TEST_CASE("A port another service listens on is refused: serve stops, run moves to a free port",
          "[service][hostile]") {
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
