#include <catch2/catch.hpp>

#include <string>

#include "orchestrator/cli/correlation_table.hpp"

namespace aerobreak::testing {
namespace {

using Json = nlohmann::ordered_json;
using Catch::Matchers::Contains;

Json critical(double level, Json estimate, Json lower, Json upper) {
  return {{"level", level}, {"at", Json::object()}, {"estimate", estimate}, {"ci95", {lower, upper}}};
}

// A summary line of GET /api/studies/ID/correlations for a per-group logistic fit in impact speed.
Json speed_fit(const std::string& response, bool adhesive, const std::string& status, Json critical_values,
               const std::string& detail = "") {
  Json fit{{"name", response + ".speed." + (adhesive ? "adhesive" : "plain")},
           {"kind", "logistic"},
           {"status", status},
           {"group", {{"/wall/adhesive", adhesive}, {"primaries", 32}}},
           {"cases", 80},
           {"validity", {{"impact_speed", {{"min", 4}, {"max", 40}}}}},
           {"response", response},
           {"dose", "impact_speed"},
           {"pooled_over", Json::array()},
           {"critical", std::move(critical_values)}};
  if (!detail.empty()) fit["detail"] = detail;
  return fit;
}

// The default study's shape: on the adhesive wall stick gives way to break-up, on the other bounce
// does; P(bounce) stays 0 on the adhesive wall and P(stick) on the other.
Json default_study_summary() {
  const Json crossing = Json::array(
      {critical(0.1, 13.4, 4.47, 19.8), critical(0.5, 24.3, 17.5, 39.6), critical(0.9, 44.0, 29.0, nullptr)});
  return {{"fits",
           {speed_fit("stick", true, "ok", crossing),
            speed_fit("bounce", true, "no-transition", Json::array(),
                      "no bounce among the 80 cases: the transition lies "
                      "outside the data (see the validity box)"),
            speed_fit("break-up", true, "separation", crossing),
            speed_fit("stick", false, "no-transition", Json::array(), "no stick among the 80 cases: ..."),
            speed_fit("bounce", false, "ok", crossing), speed_fit("break-up", false, "ok", crossing)}},
          {"fragment_sizes", Json::array()}};
}

}  // namespace

TEST_CASE("The critical-speed table has a row per fit with a crossing and folds the others into a line each") {
  const auto text = format_critical_table(default_study_summary(), "impact_speed", "physical");
  INFO(text);
  CHECK_THAT(text, Contains("v10 (m/s)") && Contains("v50 (m/s)") && Contains("v90 (m/s)"));
  CHECK_THAT(text, Contains("/wall/adhesive = true, primaries = 32\nstick "));
  CHECK_THAT(text, Contains("break-up  80  13.4 [4.47, 19.8]  24.3 [17.5, 39.6]  44* [29, open]  Firth"));
  // The four fits with a crossing are rows; the two without are one line each, naming their group.
  CHECK_THAT(text, Contains("\n  P(bounce) = 0 at every speed run: /wall/adhesive = true, primaries = 32\n"));
  CHECK_THAT(text, Contains("\n  P(stick) = 0 at every speed run: /wall/adhesive = false, primaries = 32\n"));
  CHECK_THAT(text, !Contains("\nbounce    80  -"));
}

TEST_CASE("Fits of the same reason in several groups share their line, wrapped within 100 columns") {
  Json summary = default_study_summary();
  Json other = speed_fit("bounce", true, "no-transition", Json::array(), "no bounce among the 80 cases");
  other["group"]["primaries"] = 64;
  summary["fits"].push_back(other);
  const auto text = format_critical_table(summary, "impact_speed", "physical");
  CHECK_THAT(text, Contains("\n  P(bounce) = 0 at every speed run: /wall/adhesive = true, primaries = 32;\n"
                            "    /wall/adhesive = true, primaries = 64\n"));
}

TEST_CASE("The critical-value legend explains the columns, the open ends and the extrapolation mark") {
  const auto legend = critical_table_legend();
  CHECK_THAT(legend, Contains("P of: ") && Contains("n: the cases fitted") && Contains("open: ") && Contains("*: ") &&
                         Contains("fit: "));
}

}  // namespace aerobreak::testing
