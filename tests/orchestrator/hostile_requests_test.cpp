// Requests an attacker or a careless client sends (docs/ORCHESTRATOR.md, "Limits"): each is
// answered with a 4xx and a JSON body naming the problem, before anything large is allocated or
// anything recursive runs, and the service stays up. Real `aerobreak serve`, real sockets, loopback only.
#include <fstream>
#include <string>

#include "tests/orchestrator/raw_http.hpp"
#include "tests/orchestrator/service_process.hpp"
#include "tests/support/run_command.hpp"

namespace aerobreak::testing {
namespace {

// The answer's status, with its JSON error body checked.
int refused_with(const std::string& answer) {
  INFO(answer.substr(0, 600));
  const auto body = body_of(answer);
  REQUIRE(body.is_object());
  CHECK(body.at("error").is_string());
  return status_of(answer);
}

std::string post_study(const std::string& body, const std::string& content_type = "application/json") {
  return http_request("POST", "/api/studies", "Content-Type: " + content_type + "\r\n", body);
}

bool still_serving(const ServiceProcess& service) { return service.get("/api/health").at("status") == "ok"; }

// Peak resident memory of a process, in KiB (VmHWM).
long peak_memory_kib(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

}  // namespace

TEST_CASE("An unknown path that is not UTF-8 gets a JSON 404, not an abort", "[service][hostile]") {
  ScratchDirectory scratch("invalid-path");
  ServiceProcess service(scratch.path());
  const std::string answer = round_trip(service.port(), http_request("GET", "/api/%ff"));
  CHECK(refused_with(answer) == 404);
  CHECK(still_serving(service));
}

TEST_CASE("A body nested 100,000 levels deep is refused before it is parsed", "[service][hostile]") {
  ScratchDirectory scratch("deep-body");
  ServiceProcess service(scratch.path());
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string answer = round_trip(service.port(), post_study(deep));
  CHECK(refused_with(answer) == 400);
  CHECK_THAT(body_of(answer).at("error").get<std::string>(), Catch::Contains("nest deeper than 64"));
  // 64 levels are fine as far as nesting goes (and then simply not a study).
  const std::string answer64 = round_trip(service.port(), post_study(std::string(64, '[') + std::string(64, ']')));
  CHECK(refused_with(answer64) == 422);
  CHECK(still_serving(service));
}

TEST_CASE("An axis pointer with a huge array index is refused without allocating", "[service][hostile]") {
  ScratchDirectory scratch("huge-index");
  ServiceProcess service(scratch.path());
  auto study = small_study("huge index", {0.01}, 1);
  study["axes"]["/foo/5000000"] = {{"values", {1}}};
  const long before = peak_memory_kib(service.pid());
  const std::string answer = round_trip(service.port(), post_study(study.dump()));
  CHECK(refused_with(answer) == 422);
  CHECK(body_of(answer).at("violations").dump().find("would create an array") != std::string::npos);
  // Setting it would have made an array of 5,000,001 nulls: about 300 MB.
  CHECK(peak_memory_kib(service.pid()) - before < 32 * 1024);
  CHECK(still_serving(service));
}

TEST_CASE("Bodies and parameters that are not UTF-8 or not representable get a 4xx, not a 500", "[service][hostile]") {
  ScratchDirectory scratch("encodings");
  ServiceProcess service(scratch.path());
  const int port = service.port();
  CHECK(refused_with(round_trip(port, post_study("{\"name\": \"\xff\xfe\"}"))) == 400);
  CHECK(refused_with(round_trip(port, post_study(std::string("\xff\xfe{\0\"\0}\0", 8)))) == 400);
  CHECK(refused_with(round_trip(port, post_study("{\"name\": 1e999}"))) == 400);

  // A violation that shows a long value cut at 60 bytes: the cut falls inside a two-byte character.
  auto study = small_study("preview", {0.01}, 1);
  std::string accents = "x";
  for (int i = 0; i < 60; ++i) accents += "\xc3\xa9";
  study["base"]["impact"] = {{"speed", accents}};
  study["base"]["cluster"]["generator"].erase("primaries");
  study["axes"] = {{"primaries", {{"values", {16}}}}};
  const std::string preview = round_trip(port, post_study(study.dump()));
  CHECK(refused_with(preview) == 422);

  for (const std::string target : {"/api/studies?limit=%ff", "/api/studies?offset=%c3", "/api/jobs?limit=%fe"})
    CHECK(refused_with(round_trip(port, http_request("GET", target))) == 400);
  CHECK(still_serving(service));
}

TEST_CASE("Without a token, a POST must be JSON and every request must name a loopback host", "[service][hostile]") {
  ScratchDirectory scratch("csrf");
  ServiceProcess service(scratch.path());
  const int port = service.port();
  const std::string study = small_study("csrf", {0.01}, 1).dump();
  CHECK(refused_with(round_trip(port, post_study(study, "text/plain"))) == 415);
  CHECK(refused_with(round_trip(port, post_study(study, "application/x-www-form-urlencoded"))) == 415);
  CHECK(refused_with(round_trip(port, http_request("POST", "/api/studies/1/cancel", "Content-Type: text/plain\r\n"))) ==
        415);
  CHECK(service.get("/api/studies").at("total") == 0);

  // DNS rebinding: a page at evil.example whose name now resolves to 127.0.0.1.
  const std::string rebound =
      "GET /api/health HTTP/1.1\r\nHost: evil.example:" + std::to_string(port) + "\r\nConnection: close\r\n\r\n";
  CHECK(refused_with(round_trip(port, rebound)) == 403);
  CHECK(refused_with(round_trip(port, "GET /api/health HTTP/1.0\r\n\r\n")) == 403);
  for (const std::string& host :
       {"127.0.0.1:" + std::to_string(port), "localhost:" + std::to_string(port), std::string("[::1]")}) {
    const std::string answer =
        round_trip(port, "GET /api/health HTTP/1.1\r\nHost: " + host + "\r\nConnection: close\r\n\r\n");
    CHECK(status_of(answer) == 200);
  }
  CHECK(status_of(round_trip(port, post_study(study, "application/json; charset=utf-8"))) == 201);
}

TEST_CASE("Header sections are bounded in lines and bytes while they arrive", "[service][hostile]") {
  ScratchDirectory scratch("headers");
  ServiceProcess service(scratch.path());
  std::string flood = "GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n";
  for (int i = 0; i < 200000; ++i) flood += "X-Filler-" + std::to_string(i) + ": abcdefghijklmnopqrstu\r\n";
  RawConnection many(service.port());
  many.send(flood + "\r\n");
  const std::string answer = many.receive_all();
  CHECK(refused_with(answer) == 431);
  CHECK_THAT(body_of(answer).at("error").get<std::string>(), Catch::Contains("header lines"));

  const std::string long_line =
      "GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Long: " + std::string(64 * 1024, 'a') + "\r\n\r\n";
  CHECK(refused_with(round_trip(service.port(), long_line)) == 431);
  CHECK(still_serving(service));
}

TEST_CASE("Request framing: conflicting or missing lengths are refused before the body is read", "[service][hostile]") {
  ScratchDirectory scratch("framing");
  ServiceProcess service(scratch.path());
  const int port = service.port();
  const std::string head = "POST /api/studies HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n";
  CHECK(refused_with(round_trip(port, head + "Content-Length: 2\r\nContent-Length: 40\r\n\r\n{}")) == 400);
  CHECK(refused_with(round_trip(port, head + "Content-Length: 2, 40\r\n\r\n{}")) == 400);
  CHECK(refused_with(round_trip(port, head + "Transfer-Encoding: chunked\r\n\r\n2\r\n{}\r\n0\r\n\r\n")) == 411);
  CHECK(refused_with(round_trip(port, head + "Connection: close\r\n\r\n{}")) == 411);
  CHECK(refused_with(round_trip(port, head + "Content-Length: 99999999999\r\n\r\n{}")) == 413);
  CHECK(still_serving(service));
}

TEST_CASE("An impact speed too small to reach the wall is refused", "[service][hostile]") {
  ScratchDirectory scratch("tiny-speed");
  ServiceProcess service(scratch.path());
  const std::string answer = round_trip(service.port(), post_study(small_study("tiny speed", {5e-324}, 1).dump()));
  CHECK(refused_with(answer) == 422);
  CHECK_THAT(body_of(answer).at("violations").dump(), Catch::Contains("reach the wall"));
}

TEST_CASE("An unwritable --port-file is named in a clear message", "[service][hostile]") {
  ScratchDirectory scratch("port-file");
  const auto answer = run_command(std::string(AEROBREAK_BINARY) + " serve --port 0 --store " +
                                  scratch.file("store.sqlite") + " --port-file " + scratch.file("no/such/dir/port"));
  CHECK(answer.exit_code == 1);
  CHECK_THAT(answer.text, Catch::Contains("cannot write the port file " + scratch.file("no/such/dir/port")));
}

}  // namespace aerobreak::testing
