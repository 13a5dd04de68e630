// `aerobreak serve` writes one access-log line per request on stderr (client, method and target,
// status, milliseconds), none with --quiet, and no request can forge a line.
#include <regex>

#include "tests/orchestrator/raw_http.hpp"
#include "tests/orchestrator/service_process.hpp"

namespace aerobreak::testing {

TEST_CASE("serve logs a line per request, none with --quiet", "[service]") {
  ScratchDirectory scratch("access-log");
  {
    ServiceProcess service(scratch.path());
    service.get("/api/health");
    round_trip(service.port(), http_request("GET", "/api/nothing%0d%0aforged"));
    round_trip(service.port(), "GET /api/x\x1b[31m HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
    REQUIRE(eventually([&] { return service.log().find("/api/x") != std::string::npos; }, 5s));
    const std::string log = service.log();
    INFO(log);
    CHECK(std::regex_search(log, std::regex(R"(127\.0\.0\.1:\d+ "GET /api/health" 200 \d+\.\d ms)")));
    CHECK(std::regex_search(log, std::regex(R"("GET /api/nothing%0d%0aforged" 404 )")));
    CHECK(log.find("\"GET /api/x\\x1B[31m\" 404") != std::string::npos);
    CHECK(log.find('\x1b') == std::string::npos);
  }
  ScratchDirectory quiet_scratch("access-log-quiet");
  ServiceProcess quiet(quiet_scratch.path(), {"--quiet"});
  quiet.get("/api/health");
  quiet.get("/api/studies");
  CHECK(quiet.log().find("/api/health") == std::string::npos);
  CHECK(quiet.log().find("/api/studies\"") == std::string::npos);
}

}  // namespace aerobreak::testing
