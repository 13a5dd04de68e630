// Malformed, invalid, oversized and unauthorised requests get a 4xx whose JSON body says what was
// wrong, and the service stays up and answers after each.
#include "tests/orchestrator/raw_http.hpp"
#include "tests/orchestrator/service_process.hpp"
#include "tests/support/run_command.hpp"

namespace aerobreak::testing {
namespace {

struct Answer {
  int status;
  Json body;
};

Answer post(const ServiceProcess& service, const std::string& path, const std::string& body,
            const httplib::Headers& headers = {}) {
  auto client = service.client();
  const auto response = client.Post(path.c_str(), headers, body, "application/json");
  REQUIRE(response);
  return {response->status, Json::parse(response->body, nullptr, false)};
}

Answer get(const ServiceProcess& service, const std::string& path) {
  auto client = service.client();
  const auto response = client.Get(path.c_str());
  REQUIRE(response);
  return {response->status, Json::parse(response->body, nullptr, false)};
}

bool names_pointer(const Json& body, const std::string& pointer) {
  for (const auto& violation : body.at("violations"))
    if (violation.at("pointer").get<std::string>().rfind(pointer, 0) == 0) return true;
  return false;
}

}  // namespace

TEST_CASE("Bad requests are refused with a JSON body naming the problem, and the service stays up", "[service]") {
  ScratchDirectory scratch("bad-requests");
  ServiceProcess service(scratch.path());

  SECTION("a body that is not JSON") {
    const auto answer = post(service, "/api/studies", "{\"name\": ");
    CHECK(answer.status == 400);
    CHECK_THAT(answer.body.at("error").get<std::string>(), Catch::Contains("not JSON"));
  }
  SECTION("a study that breaks its schema: each invalid field named") {
    auto study = small_study("bad", {0.01}, 1);
    study["replicates"]["count"] = 0;
    study["base"]["model"]["friction"] = -1;
    study["axes"]["warp_factor"] = {{"values", {1}}};
    const auto answer = post(service, "/api/studies", study.dump());
    CHECK(answer.status == 422);
    CHECK(names_pointer(answer.body, "/replicates/count"));
    CHECK(names_pointer(answer.body, "/axes/warp_factor"));
  }
  SECTION("every problem of a study in one answer: its replicate count does not hide its cases' errors") {
    auto study = small_study("three mistakes", {0.01}, 1);
    study["replicates"]["count"] = 0;
    study["base"]["model"]["friction"] = -1;
    study["base"]["material"]["poisson_ratio"] = 0.7;
    const auto answer = post(service, "/api/studies", study.dump());
    INFO(answer.body.dump(2));
    CHECK(answer.status == 422);
    CHECK(answer.body.at("violations").size() == 3);
    CHECK(names_pointer(answer.body, "/replicates/count"));
    CHECK(names_pointer(answer.body, "/base/model/friction"));
    CHECK(names_pointer(answer.body, "/base/material/poisson_ratio"));
    // The command-line client prints each at its field.
    const auto file = scratch.path() / "three.study.json";
    std::ofstream(file) << study.dump();
    const auto submitted =
        run_command(std::string(AEROBREAK_BINARY) + " study submit --url " + service.url() + " " + file.string());
    CHECK(submitted.exit_code == 2);
    CHECK_THAT(submitted.text, Catch::Contains("\n  /replicates/count: ") &&
                                   Catch::Contains("\n  /base/model/friction: ") &&
                                   Catch::Contains("\n  /base/material/poisson_ratio: "));
  }
  SECTION("a case made invalid by the base is named under /base") {
    auto study = small_study("bad base", {0.01}, 1);
    study["base"]["model"]["friction"] = -1;
    const auto answer = post(service, "/api/studies", study.dump());
    CHECK(answer.status == 422);
    CHECK(names_pointer(answer.body, "/base/model/friction"));
  }
  SECTION("too many cases, too many primaries, a server-side file") {
    auto many = small_study("many", {0.01}, 1);
    many["axes"]["impact_speed"] = {{"linear", {{"from", 0.001}, {"to", 0.1}, {"count", 10000}}}};
    many["replicates"]["count"] = 5;
    const auto too_many = post(service, "/api/studies", many.dump());
    CHECK(too_many.status == 422);
    CHECK(names_pointer(too_many.body, "/axes"));

    const auto huge = post(service, "/api/studies", small_study("huge", {0.01}, 1, 5000000).dump());
    CHECK(huge.status == 422);

    auto file = small_study("file", {0.01}, 1);
    file["base"]["cluster"] = {{"file", {{"path", "/etc/passwd"}}}};
    const auto server_file = post(service, "/api/studies", file.dump());
    CHECK(server_file.status == 422);
    CHECK(names_pointer(server_file.body, "/base/cluster/file"));
  }
  SECTION("a body over the size limit") {
    const auto answer = post(service, "/api/studies", std::string(2 << 20, ' '));
    CHECK(answer.status == 413);
  }
  SECTION("bad query parameters, unknown studies and endpoints") {
    const auto study = submit(service, small_study("paging", {0.01}, 1)).at("id").get<std::int64_t>();
    const std::string base = "/api/studies/" + std::to_string(study);
    CHECK(get(service, base + "/cases?limit=abc").status == 400);
    CHECK(get(service, base + "/cases?limit=100000").status == 400);
    CHECK(get(service, base + "/cases?status=sleeping").status == 400);
    CHECK(get(service, base + "/results?outcome=explode").status == 400);
    CHECK(get(service, "/api/studies/999999/progress").status == 404);
    CHECK(get(service, "/api/cases/999999").status == 404);
    const auto unknown = get(service, "/api/nothing-here");
    CHECK(unknown.status == 404);
    CHECK(unknown.body.contains("error"));
    CHECK(post(service, base + "/cancel", "").status == 200);
    CHECK(post(service, base + "/cancel", "").status == 409);
  }
  SECTION("bytes that are not HTTP") {
    RawConnection connection(service.port());
    CHECK(connection.send("\x01\x02 NOT HTTP \xff\xfe\r\n\r\n"));
    CHECK(status_of(connection.receive_all(std::chrono::seconds(5))) == 400);
  }
  CHECK(service.get("/api/health").at("status") == "ok");
}

TEST_CASE("With a token, mutating requests need it, and beyond loopback a token is required", "[service]") {
  ScratchDirectory scratch("token");
  const auto token_file = scratch.path() / "token";
  std::ofstream(token_file) << "a-long-enough-test-token-1234\n";
  ServiceProcess service(scratch.path(), {"--token-file", token_file.string()});
  const auto study = small_study("token", {0.01}, 1).dump();
  CHECK(post(service, "/api/studies", study).status == 401);
  CHECK(post(service, "/api/studies", study, {{"Authorization", "Bearer wrong-token-of-some-length"}}).status == 401);
  CHECK(post(service, "/api/studies", study, {{"Authorization", "Bearer a-long-enough-test-token-1234"}}).status ==
        201);
  CHECK(get(service, "/api/studies").status == 200);

  const auto refused = run_command(std::string(AEROBREAK_BINARY) + " serve --host 0.0.0.0 --port 0 --store " +
                                   (scratch.path() / "other.sqlite").string());
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.text, Catch::Contains("without a bearer token"));
}

}  // namespace aerobreak::testing
