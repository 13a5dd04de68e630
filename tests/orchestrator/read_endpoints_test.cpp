// Progress, the outcome table and the grid statistics over real HTTP: served from the store's
// summaries, the outcome table and the grid statistics with ETags that follow the study's results,
// and 304 for a client that has them.
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
    for (const std::string& tags : {after[i].etag, "W/" + after[i].etag, std::string("*"), "\"other\", " + after[i].etag}) {
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

}  // namespace aerobreak::testing
