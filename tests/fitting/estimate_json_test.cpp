// The one JSON shape of a mean (fitting/estimate_json.hpp) against both schemas that describe it:
// schemas/correlation.schema.json ($defs mean, the correlation documents) and schemas/openapi.json
// (MeanEstimate, the outcome table and the dashboard's grid), with and without values.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "orchestrator/fitting/estimate_json.hpp"
#include "tests/support/openapi_schema.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

std::vector<std::optional<MeanEstimate>> estimates() {
  return {std::nullopt, mean_estimate(std::vector<double>{0.4}), mean_estimate(std::vector<double>{0.4, 0.5, 0.9}),
          ratio_estimate(std::vector<double>{2, 0, 4}, std::vector<double>{1, 2, 3})};
}

}  // namespace

TEST_CASE("A mean has one JSON shape, valid against the correlation schema and the OpenAPI description",
          "[statistics][schema]") {
  const auto definitions = testing::schema_file("correlation.schema.json").at("$defs");
  const JsonSchema correlation(Json{{"$defs", definitions}, {"$ref", "#/$defs/mean"}});
  const JsonSchema openapi = testing::openapi_component("MeanEstimate");
  for (const auto& estimate : estimates()) {
    const Json json = mean_json(estimate);
    INFO(json.dump());
    CHECK(describe(correlation.validate(json)).empty());
    CHECK(describe(openapi.validate(json)).empty());
  }

  const Json three = mean_json(mean_estimate(std::vector<double>{0.4, 0.5, 0.9}));
  CHECK(three.at("n") == 3);
  CHECK(three.at("mean").get<double>() == Approx(0.6));
  const double half_width = 4.3026527297494619 * three.at("standard_error").get<double>();  // R: qt(0.975, 2)
  CHECK(three.at("ci95")[0].get<double>() == Approx(0.6 - half_width).epsilon(1e-14));
  CHECK(three.at("standard_deviation").get<double>() == Approx(std::sqrt(0.07)).epsilon(1e-14));
  const Json none = mean_json(std::nullopt);
  CHECK(none.at("n") == 0);
  CHECK(none.at("mean").is_null());
  CHECK(none.at("ci95").is_null());

  // The schemas are a contract: the shapes that came before (the dashboard's "sd", the correlation
  // documents' mean without interval) are refused by both.
  const Json dashboard_before{{"n", 3}, {"mean", 0.6}, {"sd", 0.26}, {"ci95", {0.0, 1.2}}};
  const Json correlation_before{{"n", 3}, {"mean", 0.6}, {"standard_error", 0.15}};
  for (const auto& old : {dashboard_before, correlation_before}) {
    CHECK_FALSE(correlation.validate(old).empty());
    CHECK_FALSE(openapi.validate(old).empty());
  }
}

}  // namespace aerobreak
