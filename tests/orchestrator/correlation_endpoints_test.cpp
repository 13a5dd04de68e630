// The correlation endpoints over real HTTP: `aerobreak serve` on a store that holds a finished
// study (committed through the store, no engine), and the CLI client against it.
#include <fstream>
#include <set>

#include "engine/impact/json_schema.hpp"
#include "orchestrator/store/store.hpp"
#include "tests/orchestrator/service_process.hpp"
#include "tests/store/correlation_study.hpp"
#include "tests/support/run_command.hpp"

namespace aerobreak::testing {
namespace {

struct Answer {
  int status;
  Json body;
};

Answer get(const ServiceProcess& service, const std::string& path) {
  auto client = service.client();
  const auto response = client.Get(path.c_str());
  REQUIRE(response);
  return {response->status, Json::parse(response->body, nullptr, false)};
}

const Json* fit_named(const Json& summary, const std::string& name) {
  for (const auto& fit : summary.at("fits"))
    if (fit.at("name") == name) return &fit;
  return nullptr;
}

JsonSchema correlation_schema() {
  std::ifstream file(std::string(AEROBREAK_SOURCE_DIR) + "/schemas/correlation.schema.json");
  REQUIRE(file);
  return JsonSchema(Json::parse(file));
}

// A store with study 1 finished (10 replicates) and study 2 submitted and cancelled (no results).
void prepare_store(const std::filesystem::path& file) {
  Store store(file);
  REQUIRE(finished_correlation_study(store, "served", 10, 3) == 1);
  const auto empty = store.submit_study(correlation_study_submission("empty", 1)).study_id;
  REQUIRE(store.cancel_study(empty));
}

}  // namespace

TEST_CASE("GET .../correlations serves every fit, one fit with its data and curve, and refuses bad requests",
          "[service][correlations]") {
  ScratchDirectory directory("correlation_endpoints");
  prepare_store(directory.path() / "store.sqlite");
  ServiceProcess service(directory.path());

  const Json summary = service.get("/api/studies/1/correlations");
  CHECK(summary.at("provenance").at("study") == 1);
  CHECK(summary.at("provenance").at("result_set_hash").get<std::string>().size() == 64);
  CHECK(summary.at("grid_points").at("count") == 16);
  const Json points = service.get("/api/studies/1/correlations/grid-points");
  REQUIRE(points.at("grid_points").size() == 16);
  CHECK(points.at("grid_points")[0].at("determined") == 10);
  const Json* group = fit_named(summary, "break-up.speed.g1");
  REQUIRE(group);
  CHECK(group->at("group") == Json{{"primaries", 32}});
  CHECK(group->at("cases") == 80);
  // v50 of the law the outcomes were drawn from is 0.05 for N = 32.
  const auto& v50 = group->at("critical")[1];
  CHECK(v50.at("level") == 0.5);
  CHECK(v50.at("ci95")[0].get<double>() < 0.05 * 1.5);
  CHECK(v50.at("ci95")[1].get<double>() > 0.05 / 1.5);
  CHECK(fit_named(summary, "break-up.speed.pooled.c1"));
  CHECK(fit_named(summary, "scaling.break-up.v50.c1"));

  const Json fit = service.get("/api/studies/1/correlations/break-up.speed.g1");
  CHECK(fit.at("status") == "ok");
  CHECK(fit.at("parameters").size() == 2);
  CHECK(fit.at("covariance").size() == 2);
  CHECK(fit.at("data").size() == 8);
  REQUIRE(fit.at("curves").size() == 1);
  const auto& curve = fit.at("curves")[0].at("points");
  CHECK(curve.size() == 50);
  CHECK(curve.front().at("dose") == 0.01);
  for (const auto& point : curve) CHECK(point.at("ci95")[0].get<double>() <= point.at("value").get<double>());
  CHECK(fit.at("validity").at("impact_speed").at("max") == 0.3);

  // ETags: a client holding the current document gets 304 without a body; each document has its own.
  auto client = service.client();
  const auto tagged = client.Get("/api/studies/1/correlations");
  REQUIRE(tagged);
  const std::string etag = tagged->get_header_value("ETag");
  CHECK(etag.size() == 34);
  const auto unchanged = client.Get("/api/studies/1/correlations", httplib::Headers{{"If-None-Match", etag}});
  REQUIRE(unchanged);
  CHECK(unchanged->status == 304);
  CHECK(unchanged->body.empty());
  const auto other =
      client.Get("/api/studies/1/correlations/break-up.speed.g1", httplib::Headers{{"If-None-Match", etag}});
  REQUIRE(other);
  CHECK(other->status == 200);
  CHECK(other->get_header_value("ETag") != etag);

  const Answer unknown = get(service, "/api/studies/1/correlations/break-up.speed.g9");
  CHECK(unknown.status == 404);
  CHECK(unknown.body.at("error").get<std::string>().find("no fit 'break-up.speed.g9'") != std::string::npos);
  const Answer covariate = get(service, "/api/studies/1/correlations?covariates=angle");
  CHECK(covariate.status == 400);
  CHECK(covariate.body.at("error").get<std::string>().find("covariate 'angle' is not an axis of study 1") !=
        std::string::npos);
  const Answer no_results = get(service, "/api/studies/2/correlations");
  CHECK(no_results.status == 404);
  CHECK(no_results.body.at("error").get<std::string>().find("no results") != std::string::npos);
  CHECK(get(service, "/api/studies/99/correlations").status == 404);
  CHECK(get(service, "/api/studies/1/correlations?covariates=" + std::string(300, 'x')).status == 400);
  const Json chosen = service.get("/api/studies/1/correlations?covariates=N");
  CHECK(chosen.at("request").at("covariates")[0].at("axis") == "primaries");

  // The CLI client prints the critical speeds from the same endpoint.
  const auto printed = run_command(std::string(AEROBREAK_BINARY) + " study correlations 1 --url " + service.url());
  CHECK(printed.exit_code == 0);
  INFO(printed.text);
  CHECK(printed.text.find("v50 (d/tau)") != std::string::npos);
  CHECK(printed.text.find("[95% CI]") != std::string::npos);
  CHECK(printed.text.find("break-up.speed.pooled.c1") != std::string::npos);
  CHECK(service.kill(SIGTERM) == 0);
}

TEST_CASE("Every served correlation document is valid against schemas/correlation.schema.json",
          "[service][correlations]") {
  ScratchDirectory directory("correlation_schema");
  prepare_store(directory.path() / "store.sqlite");
  ServiceProcess service(directory.path());
  const JsonSchema schema = correlation_schema();

  const auto check = [&schema](const Json& document, const std::string& name) {
    INFO(name << ":\n" << describe(schema.validate(document)));
    CHECK(schema.validate(document).empty());
  };
  const Json summary = service.get("/api/studies/1/correlations");
  check(summary, "summary");
  std::vector<std::string> names{"grid-points"};
  for (const auto& fit : summary.at("fits")) names.push_back(fit.at("name"));
  for (const auto& name : summary.at("fragment_sizes")) names.push_back(name);
  std::set<std::string> kinds;
  for (const auto& name : names) {
    const Json document = service.get("/api/studies/1/correlations/" + name);
    kinds.insert(document.at("kind").get<std::string>());
    check(document, name);
  }
  // Every kind of document was among them, a fit with covariates too.
  CHECK(kinds == std::set<std::string>{"grid-points", "logistic", "multinomial", "scaling", "retained-fraction",
                                       "fragment-sizes"});
  check(service.get("/api/studies/1/correlations/break-up.energy.pooled.c1?covariates=N"), "pooled energy fit");

  // The schema is a contract, not a formality: a document that breaks it is refused.
  Json broken = service.get("/api/studies/1/correlations/break-up.speed.g1");
  broken["status"] = "fine";
  CHECK_FALSE(schema.validate(broken).empty());
  broken = summary;
  broken["fits"][0].erase("validity");
  CHECK_FALSE(schema.validate(broken).empty());
  CHECK(service.kill(SIGTERM) == 0);
}

}  // namespace aerobreak::testing
