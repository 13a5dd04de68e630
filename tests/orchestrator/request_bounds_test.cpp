// What a client sends beyond a body is bounded too: Range headers cannot make an answer longer
// than the whole answer plus a few part headers, and an unsatisfiable one gets 416; a query
// parameter that takes one value refuses a second on every endpoint; every JSON pointer a study
// names (an axis, the search axis) is bounded in length, depth and array growth before anything
// is set; and a search whose base sets the searched field is refused as a grid study is. Real
// `aerobreak serve`, real sockets, loopback only.
#include <string>

#include "tests/orchestrator/raw_http.hpp"
#include "tests/orchestrator/service_process.hpp"

namespace aerobreak::testing {
namespace {

std::string get_with(const std::string& target, const std::string& headers) {
  return http_request("GET", target, headers);
}

std::string header_of(const std::string& answer, const std::string& name) {
  const auto head_end = answer.find("\r\n\r\n");
  const std::string head = answer.substr(0, head_end);
  const auto at = head.find("\r\n" + name + ": ");
  if (at == std::string::npos) return {};
  const auto start = at + name.size() + 4;
  return head.substr(start, head.find("\r\n", start) - start);
}

std::string body_text(const std::string& answer) { return answer.substr(answer.find("\r\n\r\n") + 4); }

std::string many_parts(int count) {
  std::string value = "bytes=";
  for (int i = 0; i < count; ++i) value += i ? ",0-" : "0-";
  return value;
}

std::string post_study(const Json& study) {
  return http_request("POST", "/api/studies", "Content-Type: application/json\r\n", study.dump());
}

Json search_study() {
  Json study = small_study("search", {0.01}, 1);
  study["axes"] = {{"gamma_over_kn", {{"values", {0.001}}}}};
  study["base"]["material"].erase("gamma_over_kn");
  study["search"] = {{"axis", "impact_speed"}, {"range", {{"from", 0.005}, {"to", 0.3}}}, {"relative_width", 0.5}};
  return study;
}

}  // namespace

TEST_CASE("Range requests are bounded: parts merged, many parts answered whole, unsatisfiable ones 416",
          "[service][hostile]") {
  ScratchDirectory scratch("ranges");
  ServiceProcess service(scratch.path());
  const int port = service.port();
  for (const std::string target : {"/", "/api/health", "/api/openapi.json"}) {
    INFO(target);
    const std::string whole = round_trip(port, get_with(target, ""));
    REQUIRE(status_of(whole) == 200);
    const std::size_t length = body_text(whole).size();

    // 1,500 parts "0-" are one part once merged: the whole answer, once.
    const std::string repeated = round_trip(port, get_with(target, "Range: " + many_parts(1500) + "\r\n"));
    CHECK(status_of(repeated) == 206);
    CHECK(body_text(repeated).size() == length);
    const std::string whole_range = "bytes 0-" + std::to_string(length - 1) + "/" + std::to_string(length);
    CHECK(header_of(repeated, "Content-Range") == whole_range);

    // Overlapping parts merge; two apart are multipart; more than 8 apart are the whole answer.
    const std::string merged = round_trip(port, get_with(target, "Range: bytes=0-9, 5-19\r\n"));
    CHECK(status_of(merged) == 206);
    CHECK(body_text(merged) == body_text(whole).substr(0, 20));
    const std::string two = round_trip(port, get_with(target, "Range: bytes=0-1,10-11\r\n"));
    CHECK(status_of(two) == 206);
    CHECK_THAT(header_of(two, "Content-Type"), Catch::StartsWith("multipart/byteranges; boundary="));
    CHECK(body_text(two).size() < 400);
    std::string apart = "bytes=";
    for (int i = 0; i < 20; ++i) {
      if (i) apart += ',';
      apart += std::to_string(3 * i) + "-" + std::to_string(3 * i);
    }
    const std::string scattered = round_trip(port, get_with(target, "Range: " + apart + "\r\n"));
    CHECK(status_of(scattered) == 200);
    CHECK(body_text(scattered).size() == length);

    // Beyond the answer: 416 naming its length, with a JSON body.
    const std::string beyond = round_trip(port, get_with(target, "Range: bytes=99999999999-\r\n"));
    CHECK(status_of(beyond) == 416);
    CHECK(header_of(beyond, "Content-Range") == "bytes */" + std::to_string(length));
    CHECK(body_of(beyond).at("error").is_string());
    // A client that accepts gzip gets the bytes of the answer as it is, not of its gzip form.
    const std::string gzip_asked = round_trip(port, get_with(target, "Range: bytes=0-9\r\nAccept-Encoding: gzip\r\n"));
    CHECK(header_of(gzip_asked, "Content-Encoding").empty());
    CHECK(body_text(gzip_asked) == body_text(whole).substr(0, 10));
    // The last 10 bytes, and an If-Range that names another version: the whole answer.
    const std::string suffix = round_trip(port, get_with(target, "Range: bytes=-10\r\n"));
    CHECK(body_text(suffix) == body_text(whole).substr(length - 10));
    CHECK(status_of(round_trip(port, get_with(target, "Range: bytes=0-1\r\nIf-Range: \"other\"\r\n"))) == 200);
  }
}

TEST_CASE("A header line or request line past 8 KiB is refused by name, and its connection closed",
          "[service][hostile]") {
  ScratchDirectory scratch("long-lines");
  ServiceProcess service(scratch.path());
  const int port = service.port();
  // 10,000 parts of a Range fit in the 32 KiB of headers, not in one line: 431, once.
  const std::string ranged = round_trip(port, get_with("/api/health", "Range: " + many_parts(10000) + "\r\n"));
  CHECK(status_of(ranged) == 431);
  CHECK(body_of(ranged).at("error") == "a header line is longer than 8192 bytes");
  CHECK(ranged.find("HTTP/1.1", 1) == std::string::npos);
  const std::string long_target = round_trip(port, get_with("/api/health?" + std::string(9000, 'a'), ""));
  CHECK(status_of(long_target) == 414);
  CHECK(body_of(long_target).at("error") == "the request line is longer than 8192 bytes");
  // A header line of 8 KiB is served.
  const std::string longest = "X-Long: " + std::string(8192 - 10, 'a') + "\r\n";
  CHECK(status_of(round_trip(port, get_with("/api/health", longest))) == 200);
}

TEST_CASE("A query parameter that takes one value refuses a second, on every endpoint", "[service][hostile]") {
  ScratchDirectory scratch("repeated-parameters");
  ServiceProcess service(scratch.path());
  const int port = service.port();
  submit(service, small_study("parameters", {0.01}, 1));
  for (const std::string target :
       {"/api/studies/1/correlations?covariates=primaries&covariates=bogus", "/api/studies?limit=5&limit=6",
        "/api/studies/1/cases?status=done&status=queued", "/api/studies/1/results?outcome=stick&outcome=bounce",
        "/api/studies/1/case-table?offset=0&offset=1", "/api/studies/1/tables?format=csv&format=json"}) {
    INFO(target);
    const std::string answer = round_trip(port, http_request("GET", target));
    CHECK(status_of(answer) == 400);
    CHECK_THAT(body_of(answer).at("violations").dump(), Catch::Contains("\"parameter\""));
  }
  // axis.NAME takes several values (any of them).
  CHECK(status_of(round_trip(port, http_request("GET",
                                                "/api/studies/1/case-table?axis.impact_speed=0.01&"
                                                "axis.impact_speed=0.02"))) == 200);
}

TEST_CASE("Every JSON pointer a study names is bounded before anything is set, the search axis too",
          "[service][hostile]") {
  ScratchDirectory scratch("pointers");
  ServiceProcess service(scratch.path());
  const int port = service.port();

  // The search axis at index 5,000,000: refused at once (before, 11 s and 70 MB at 1,000,000).
  auto indexed = search_study();
  indexed["search"]["axis"] = "/model/friction/5000000";
  const auto asked = std::chrono::steady_clock::now();
  const std::string answer = round_trip(port, post_study(indexed));
  CHECK(std::chrono::steady_clock::now() - asked < 2s);
  CHECK(status_of(answer) == 422);
  CHECK_THAT(body_of(answer).at("violations").dump(),
             Catch::Contains("/search/axis") && Catch::Contains("would create an array"));

  // Too deep, too long: for an axis and for the search axis alike.
  const std::string deep = "/model/a/b/c/d/e/f/g/h/i";
  const std::string long_name = "/model/" + std::string(300, 'x');
  for (const std::string& pointer : {deep, long_name}) {
    auto axis = small_study("axis", {0.01}, 1);
    axis["axes"][pointer] = {{"values", {1}}};
    const std::string by_axis = round_trip(port, post_study(axis));
    CHECK(status_of(by_axis) == 422);
    auto search = search_study();
    search["search"]["axis"] = pointer;
    const std::string by_search = round_trip(port, post_study(search));
    CHECK(status_of(by_search) == 422);
    CHECK_THAT(body_of(by_search).at("violations").dump(), Catch::Contains("/search/axis"));
  }
  CHECK(service.get("/api/studies").at("total") == 0);
}

TEST_CASE("A search whose base also sets the searched field is refused, as a grid study is", "[service][hostile]") {
  ScratchDirectory scratch("search-base");
  ServiceProcess service(scratch.path());
  auto study = search_study();
  study["base"]["impact"] = {{"speed", 0.01}};
  const std::string answer = round_trip(service.port(), post_study(study));
  CHECK(status_of(answer) == 422);
  CHECK_THAT(body_of(answer).at("violations").dump(),
             Catch::Contains("/base/impact/speed") && Catch::Contains("is set by the search"));
}

}  // namespace aerobreak::testing
