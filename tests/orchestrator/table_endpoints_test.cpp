// GET and HEAD /api/studies/ID/tables over real HTTP on a store holding a finished study: content
// types and file names of every format, HEAD without a body, kind=fit with its strict mode, and
// requests the study cannot serve answered 4xx with a JSON body naming the parameter; kind=fit at
// sizes the study did not run (the fit pooled over its sizes), inside or outside its validity box.
#include <map>

#include "orchestrator/store/sqlite_database.hpp"
#include "tests/export/pooled_size_study.hpp"
#include "tests/orchestrator/service_process.hpp"

namespace aerobreak::testing {
namespace {

struct Answer {
  int status;
  std::string body;
  httplib::Headers headers;
  std::string header(const std::string& name) const {
    const auto found = headers.find(name);
    return found == headers.end() ? std::string() : found->second;
  }
};

Answer get(const ServiceProcess& service, const std::string& path, bool head = false) {
  auto client = service.client();
  const auto response = head ? client.Head(path.c_str()) : client.Get(path.c_str());
  REQUIRE(response);
  return {response->status, response->body, response->headers};
}

void check_refused(const ServiceProcess& service, const std::string& path, int status, const std::string& parameter) {
  const auto answer = get(service, path);
  INFO(path << " -> " << answer.body);
  CHECK(answer.status == status);
  const auto body = Json::parse(answer.body);
  CHECK(body.at("violations").at(0).at("parameter") == parameter);
}

}  // namespace

TEST_CASE("Lookup-table endpoint: formats, file names, HEAD, fits and refusals naming the parameter",
          "[service][export]") {
  ScratchDirectory scratch("table_endpoints");
  ServiceProcess service(scratch.path());
  const auto id = submit(service, small_study("tables", {0.005, 0.3}, 3, 8)).at("id").get<std::int64_t>();
  REQUIRE(eventually([&] { return study_complete(service, id); }, 120s));
  const std::string tables = "/api/studies/" + std::to_string(id) + "/tables";

  struct Expected {
    std::string query, type, file;
  };
  const std::string stem = "study" + std::to_string(id);
  for (const auto& expected : std::vector<Expected>{
           {"?format=csv", "text/csv", stem + "_grid.csv"},
           {"?format=dat&kind=sections", "text/plain", stem + "_sections.dat"},
           {"?format=json", "application/json", stem + "_grid.json"},
           {"?format=hdf5", "application/x-hdf5", stem + "_grid.h5"},
           {"?format=melcor", "text/plain", stem + "_grid_melcor_tf.inp"},
           {"?format=openfoam&quantity=restitution", "text/plain", stem + "_grid_restitution_table2d"},
           {"?format=openfoam&layout=csv", "text/csv", stem + "_grid_p_stick.csv"}}) {
    const auto answer = get(service, tables + expected.query);
    INFO(expected.query << " -> " << answer.body.substr(0, 300));
    REQUIRE(answer.status == 200);
    CHECK(answer.header("Content-Type").starts_with(expected.type));
    CHECK(answer.header("Content-Disposition") == "attachment; filename=\"" + expected.file + "\"");
    CHECK_FALSE(answer.body.empty());
  }
  CHECK(get(service, tables + "?format=hdf5").body.substr(0, 8) == std::string("\x89HDF\r\n\x1a\n", 8));

  SECTION("HEAD answers like GET, without a body; the dashboard asks it before it shows downloads") {
    const auto head = get(service, tables + "?format=csv", true);
    CHECK(head.status == 200);
    CHECK(head.body.empty());
    CHECK(head.header("Content-Disposition").find("_grid.csv") != std::string::npos);
    CHECK(get(service, "/api/studies/999/tables?format=csv", true).status == 404);
  }

  SECTION("kind=fit: P(stick) and P(break-up) with bands at the speeds asked for; strict refuses extrapolation") {
    const auto fit = get(service, tables + "?format=json&kind=fit&speeds=0.01,0.1");
    INFO(fit.body.substr(0, 500));
    REQUIRE(fit.status == 200);
    const auto document = Json::parse(fit.body);
    CHECK(document.at("kind") == "fit");
    for (const auto& column : document.at("columns"))
      if (column.at("name") == "inside_validity") CHECK(column.at("values") == Json::array({1.0, 1.0}));
    check_refused(service, tables + "?kind=fit&speeds=3&strict=true", 422, "speeds");
    CHECK(get(service, tables + "?kind=fit&speeds=3").status == 200);
  }

  SECTION("refusals: 400 for bad parameters, 422 for a material outside the study's range, 404 for no study") {
    check_refused(service, tables + "?format=xlsx", 400, "format");
    check_refused(service, tables + "?kind=everything", 400, "kind");
    check_refused(service, tables + "?colour=red", 400, "colour");
    check_refused(service, tables + "?youngs_modulus=1e10&poisson_ratio=0.3", 400, "density");
    check_refused(service, tables + "?section_ratio=0.5&kind=sections", 400, "section_ratio");
    check_refused(service, tables + "?select=wall_adhesive", 400, "select");
    check_refused(service, tables + "?select=wall_adhesive:1", 422,
                  "select");  // this study has one wall: no such column
    // gamma/k_n = 3 gamma (1 - nu^2) / (E d) = 0.0273 for this material; the study has 0.001 only.
    check_refused(service,
                  tables + "?youngs_modulus=1e10&poisson_ratio=0.3&density=1725&surface_energy=2&diameter=2e-8", 422,
                  "surface_energy");
    CHECK(get(service, "/api/studies/999/tables?format=csv").status == 404);
  }
}

TEST_CASE("Lookup-table endpoint: kind=fit at sizes not run, flagged or refused by strict naming sizes",
          "[service][export]") {
  ScratchDirectory scratch("table_endpoints_sizes");
  std::int64_t id = 0;
  {
    Store store(scratch.path() / "store.sqlite");  // N = 32 and 128, closed before the service opens it
    id = fill_pooled_study(store);
  }
  ServiceProcess service(scratch.path());
  const std::string tables = "/api/studies/" + std::to_string(id) + "/tables?kind=fit&speeds=0.05";
  const auto fit = get(service, tables + "&format=json&sizes=64,512");
  INFO(fit.body.substr(0, 500));
  REQUIRE(fit.status == 200);
  std::map<std::string, Json> columns;
  const auto document = Json::parse(fit.body);
  for (const auto& column : document.at("columns")) columns[column.at("name").get<std::string>()] = column.at("values");
  CHECK(columns.at("primaries") == Json::array({64.0, 512.0}));
  CHECK(columns.at("inside_validity") == Json::array({1.0, 0.0}));  // between 32 and 128: inside; 512: extrapolated
  CHECK(columns.at("model") == Json::array({1.0, 1.0}));
  CHECK(get(service, tables + "&sizes=64&strict=true").status == 200);
  check_refused(service, tables + "&sizes=512&strict=true", 422, "sizes");
  const auto refused = Json::parse(get(service, tables + "&sizes=16&strict=true").body);
  CHECK(
      refused.at("violations").at(0).at("message").get<std::string>().find("from 3.200000000e+01 to 1.280000000e+02") !=
      std::string::npos);
}

}  // namespace aerobreak::testing

namespace aerobreak::testing {

// A table is built once per result-set version and request, then kept: the same ETag (304 for a
// client holding it) until a result changes; gzip for a client that accepts it, the same table once
// inflated.
TEST_CASE("Lookup-table endpoint: kept per result-set version and request, with an ETag, sent gzip",
          "[service][export]") {
  ScratchDirectory scratch("table_endpoints_kept");
  std::int64_t id = 0;
  {
    Store store(scratch.path() / "store.sqlite");
    id = fill_pooled_study(store);
  }
  ServiceProcess service(scratch.path());
  const std::string csv = "/api/studies/" + std::to_string(id) + "/tables?format=csv";
  auto client = service.client();
  const auto first = client.Get(csv.c_str(), httplib::Headers{{"Accept-Encoding", "identity"}});
  REQUIRE(first);
  REQUIRE(first->status == 200);
  const std::string etag = first->get_header_value("ETag");
  CHECK_FALSE(etag.empty());
  CHECK(first->get_header_value("Content-Encoding").empty());
  const auto again = client.Get(csv.c_str(), httplib::Headers{{"If-None-Match", etag}});
  REQUIRE(again);
  CHECK(again->status == 304);
  CHECK(again->body.empty());
  const auto compressed = client.Get(csv.c_str(), httplib::Headers{{"Accept-Encoding", "gzip"}});
  REQUIRE(compressed);
  CHECK(compressed->get_header_value("Content-Encoding") == "gzip");
  CHECK(compressed->get_header_value("ETag") == etag);
  CHECK(compressed->body == first->body);
  const auto json = client.Get((csv.substr(0, csv.find('?')) + "?format=json").c_str());
  REQUIRE(json);
  CHECK(json->get_header_value("ETag") != etag);

  // A changed result set: the table is built again, under a new tag.
  SqliteDatabase(service.store_file()).execute("UPDATE results SET outcome = 'undetermined' WHERE case_id = 1");
  const auto changed = client.Get(csv.c_str(), httplib::Headers{{"If-None-Match", etag}});
  REQUIRE(changed);
  CHECK(changed->status == 200);
  CHECK(changed->get_header_value("ETag") != etag);
  CHECK(changed->body != first->body);
  CHECK(service.kill(SIGTERM) == 0);
}

}  // namespace aerobreak::testing
