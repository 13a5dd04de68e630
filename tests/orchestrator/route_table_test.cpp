// The service's route table (orchestrator/service/routes.cpp) against its description,
// schemas/openapi.json: every route is a documented operation, with its operationId and the
// security the service enforces (a bearer token for every request but GET and HEAD), every
// documented operation is a route, and every one answers over real HTTP with a status its
// description lists: a handler's answer, never the router's "no endpoint". The service is a real
// `aerobreak serve` with worker jobs of the engine's test double (tests/support/synthetic_worker.cpp).
#include <cctype>
#include <set>

#include "orchestrator/service/routes.hpp"
#include "tests/orchestrator/synthetic_service.hpp"

namespace aerobreak::testing {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Each documented operation as "METHOD path".
std::set<std::string> documented_operations(const Json& description) {
  std::set<std::string> out;
  for (const auto& [path, item] : description.at("paths").items())
    for (const auto& [method, operation] : item.items())
      if (method == "get" || method == "post") out.insert(lower(method) + " " + path);
  return out;
}

// The documented path with its parameters filled: a study's id, a case's id, a fit's name.
std::string filled(std::string path, std::int64_t study, std::int64_t case_id, const std::string& fit) {
  const auto fill = [&path](const std::string& parameter, const std::string& value) {
    if (const auto at = path.find(parameter); at != std::string::npos) path.replace(at, parameter.size(), value);
  };
  fill("{name}", fit);
  fill("{id}", std::to_string(path.starts_with("/api/cases/") ? case_id : study));
  return path;
}

Json grid_study() {
  Json speeds = Json::array({0.01, 0.02, 0.04, 0.08, 0.16});
  return small_study("routes", speeds, 4);
}

}  // namespace

TEST_CASE("Every route is an operation of schemas/openapi.json, and every operation a route", "[service][routes]") {
  const Json description = openapi();
  std::set<std::string> routed;
  for (const Route& route : routes()) {
    INFO(route.method << " " << route.path);
    const std::string method = lower(route.method);
    CHECK(routed.insert(method + " " + std::string(route.path)).second);
    REQUIRE(description.at("paths").contains(std::string(route.path)));
    const Json& item = description.at("paths").at(std::string(route.path));
    REQUIRE(item.contains(method));
    const Json& operation = item.at(method);
    CHECK(operation.at("operationId").get<std::string>() == route.operation_id);
    // The service asks a token of every request but GET and HEAD (docs/ORCHESTRATOR.md, "Limits").
    const Json expected = method == "get" ? Json::array() : Json::array({{{"bearer", Json::array()}}});
    CHECK(operation.at("security") == expected);
    CHECK_NOTHROW(route_pattern(route));
  }
  CHECK(routed == documented_operations(description));
}

TEST_CASE("Every documented operation answers over HTTP with a status its description lists", "[service][routes]") {
  ScratchDirectory scratch("routes");
  ServiceProcess service(scratch.path(), synthetic_worker_options());
  const Json study = grid_study();
  const auto study_id = submit(service, study).at("id").get<std::int64_t>();
  REQUIRE(eventually([&] { return study_complete(service, study_id); }, 120s));
  const auto case_id = service.get("/api/studies/" + std::to_string(study_id) + "/cases?limit=1")
                           .at("items")
                           .at(0)
                           .at("id")
                           .get<std::int64_t>();
  const auto fits = service.get("/api/studies/" + std::to_string(study_id) + "/correlations").at("fits");
  REQUIRE_FALSE(fits.empty());
  const std::string fit = fits.at(0).at("name").get<std::string>();

  const Json description = openapi();
  auto client = service.client();
  int answered = 0;
  for (const auto& [path, item] : description.at("paths").items()) {
    for (const auto& [method, operation] : item.items()) {
      const std::string target = filled(path, study_id, case_id, fit);
      INFO(method << " " << target);
      const auto response =
          method == "post" ? client.Post(target.c_str(), study.dump(), "application/json") : client.Get(target.c_str());
      REQUIRE(response);
      INFO("-> " << response->status << " " << response->body.substr(0, 300));
      CHECK(operation.at("responses").contains(std::to_string(response->status)));
      CHECK(response->body.find("no endpoint") == std::string::npos);
      ++answered;
    }
  }
  CHECK(answered == static_cast<int>(routes().size()));
}

}  // namespace aerobreak::testing
