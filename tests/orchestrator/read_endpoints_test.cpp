// Progress, the outcome table and the grid statistics over real HTTP: served from the store's
// summaries, the outcome table and the grid statistics with ETags that follow the study's results,
// and 304 for a client that has them. A study's and a case's units; the study templates; answers
// compressed with gzip (never Brotli per request).
#include <fstream>

#include "tests/orchestrator/service_process.hpp"

namespace aerobreak::testing {
namespace {

struct Answer {
  int status = 0;
  std::string etag;
  std::string body;
};

Answer get(const ServiceProcess& service, const std::string& path, const std::string& if_none_match = "") {
  auto client = service.client();
  httplib::Headers headers;
  if (!if_none_match.empty()) headers.emplace("If-None-Match", if_none_match);
  const auto response = client.Get(path.c_str(), headers);
  REQUIRE(response);
  return {response->status, response->get_header_value("ETag"), response->body};
}

}  // namespace

// The outcome table and the dashboard's grid statistics are both kept by the study's versions
// (VersionedDocuments): each carries an ETag that follows the study's results.
TEST_CASE("The outcome table's and the grid statistics' ETags follow the study's results, and If-None-Match gets 304",
          "[service]") {
  ScratchDirectory scratch("read-endpoints");
  ServiceProcess service(scratch.path());
  const auto study = submit(service, small_study("tagged", {0.005, 0.08}, 2)).at("id").get<std::int64_t>();
  const std::vector<std::string> paths{"/api/studies/" + std::to_string(study) + "/outcomes",
                                       "/api/studies/" + std::to_string(study) + "/grid"};
  std::vector<Answer> before;
  for (const auto& path : paths) before.push_back(get(service, path));
  REQUIRE(eventually([&] { return study_complete(service, study); }, 120s));
  const auto progress = service.get("/api/studies/" + std::to_string(study) + "/progress");
  CHECK(progress.at("counts").at("done") == 4);
  CHECK(progress.at("complete") == true);

  std::vector<Answer> after;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    INFO(paths[i]);
    REQUIRE(before[i].status == 200);
    REQUIRE_FALSE(before[i].etag.empty());
    after.push_back(get(service, paths[i]));
    REQUIRE(after[i].status == 200);
    CHECK(after[i].etag != before[i].etag);
    const auto table = Json::parse(after[i].body);
    REQUIRE(table.at("grid_points").size() == 2);
    for (const auto& point : table.at("grid_points")) CHECK(point.at("finished") == 2);
    for (const std::string& tags :
         {after[i].etag, "W/" + after[i].etag, std::string("*"), "\"other\", " + after[i].etag}) {
      INFO("If-None-Match: " << tags);
      const Answer cached = get(service, paths[i], tags);
      CHECK(cached.status == 304);
      CHECK(cached.body.empty());
      CHECK(cached.etag == after[i].etag);
    }
    const Answer outdated = get(service, paths[i], before[i].etag);
    CHECK(outdated.status == 200);
    CHECK(outdated.body == after[i].body);
  }
  CHECK(after[0].etag != after[1].etag);

  // A client that accepts gzip gets the body compressed once per version (not by cpp-httplib on
  // every request); the client library inflates it back to the same document.
  for (std::size_t i = 0; i < paths.size(); ++i) {
    INFO(paths[i]);
    auto client = service.client();
    const auto compressed = client.Get(paths[i].c_str(), httplib::Headers{{"Accept-Encoding", "gzip"}});
    REQUIRE(compressed);
    CHECK(compressed->status == 200);
    CHECK(compressed->get_header_value("Content-Encoding") == "gzip");
    CHECK(compressed->body == after[i].body);
    const auto plain = client.Get(paths[i].c_str(), httplib::Headers{{"Accept-Encoding", "identity"}});
    REQUIRE(plain);
    CHECK(plain->get_header_value("Content-Encoding").empty());
    CHECK(plain->body == after[i].body);
  }

  // Another study, even one sharing finished cases, changes nothing of this one.
  const auto other = submit(service, small_study("sharing", {0.08, 0.3}, 2)).at("id").get<std::int64_t>();
  REQUIRE(eventually([&] { return study_complete(service, other); }, 120s));
  for (std::size_t i = 0; i < paths.size(); ++i) CHECK(get(service, paths[i], after[i].etag).status == 304);
  const auto shared = Json::parse(get(service, "/api/studies/" + std::to_string(other) + "/outcomes").body);
  CHECK(shared.at("grid_points")[0].at("finished") == 2);
  CHECK(service.kill(SIGTERM) == 0);
}

TEST_CASE("Progress, outcomes and grid of a study that does not exist are 404 with a JSON body", "[service]") {
  ScratchDirectory scratch("read-endpoints-404");
  ServiceProcess service(scratch.path());
  for (const char* path : {"/api/studies/999/progress", "/api/studies/999/outcomes", "/api/studies/999/grid"}) {
    INFO(path);
    const Answer answer = get(service, path);
    CHECK(answer.status == 404);
    CHECK(Json::parse(answer.body).at("error") == "no study 999");
  }
}

TEST_CASE("A study's and a case's answers name their units, and the templates hold the default study", "[service]") {
  ScratchDirectory scratch("read-endpoints-units");
  ServiceProcess service(scratch.path());
  const auto templates = service.get("/api/templates");
  REQUIRE(templates.at("items").size() == 1);
  const auto& item = templates.at("items")[0];
  CHECK(item.at("name") == "default");
  std::ifstream file(std::string(AEROBREAK_SOURCE_DIR) + "/studies/default.study.json");
  auto expected = Json::parse(file);
  expected.erase("$schema");
  CHECK(item.at("document") == expected);

  // The default study made one case: physical, in SI.
  Json physical = item.at("document");
  physical["name"] = "physical, one case";
  physical["axes"] = {{"impact_speed", {{"values", {8}}}}, {"primaries", {{"values", {8}}}}};
  physical["replicates"] = {{"count", 1}, {"seed", 1}};
  const auto physical_id = submit(service, physical).at("id").get<std::int64_t>();
  const auto reduced_id = submit(service, small_study("reduced", {0.01}, 1, 8)).at("id").get<std::int64_t>();
  const Json si{{"system", "physical"}, {"length", "m"},  {"mass", "kg"},
                {"time", "s"},          {"speed", "m/s"}, {"energy", "J"}};
  const Json reduced{{"system", "reduced"}, {"length", "d"},    {"mass", "m"},
                     {"time", "tau"},       {"speed", "d/tau"}, {"energy", "k_n d^2"}};
  for (const auto& [id, units] : {std::pair{physical_id, si}, std::pair{reduced_id, reduced}}) {
    INFO("study " << id);
    const auto study = service.get("/api/studies/" + std::to_string(id));
    CHECK(study.at("units") == units);
    const auto cases = service.get("/api/studies/" + std::to_string(id) + "/cases");
    const auto detail = service.get("/api/cases/" + std::to_string(cases.at("items")[0].at("id").get<std::int64_t>()));
    CHECK(detail.at("units") == units);
  }
  for (const auto& study : service.get("/api/progress").at("items")) CHECK(study.at("units").at("system").is_string());
  for (const auto id : {physical_id, reduced_id})
    REQUIRE(eventually([&] { return study_complete(service, id); }, 120s));
}

TEST_CASE("Answers of 1 kB or more go out gzip-compressed for a client that accepts gzip, none with Brotli",
          "[service]") {
  ScratchDirectory scratch("read-endpoints-gzip");
  ServiceProcess service(scratch.path());
  const auto plain = service.client().Get("/api/openapi.json", httplib::Headers{{"Accept-Encoding", "identity"}});
  REQUIRE(plain);
  REQUIRE(plain->body.size() > 1024);
  CHECK(plain->get_header_value("Content-Encoding").empty());
  for (const std::string path : {"/api/openapi.json", "/api/templates", "/"}) {
    INFO(path);
    const auto browser = service.client().Get(path.c_str(), httplib::Headers{{"Accept-Encoding", "gzip, deflate, br"}});
    REQUIRE(browser);
    CHECK(browser->status == 200);
    CHECK(browser->get_header_value("Content-Encoding") == "gzip");
    CHECK(browser->get_header_value("Vary") == "Accept-Encoding");
    const auto brotli_only = service.client().Get(path.c_str(), httplib::Headers{{"Accept-Encoding", "br"}});
    REQUIRE(brotli_only);
    CHECK(brotli_only->get_header_value("Content-Encoding").empty());
    CHECK(brotli_only->body == browser->body);  // the client inflated the gzip body
  }
  for (const std::string accepted : {"gzip", "gzip, deflate, br"}) {
    INFO(accepted);
    const auto small = service.client().Get("/api/health", httplib::Headers{{"Accept-Encoding", accepted}});
    REQUIRE(small);
    CHECK(small->body.size() < 1024);
    CHECK(small->get_header_value("Content-Encoding").empty());
  }
}

}  // namespace aerobreak::testing
