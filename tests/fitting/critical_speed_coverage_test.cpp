// Coverage of the profile-likelihood interval of v50: on 400 synthetic studies drawn from a known
// logistic law, the 95 % interval must contain the true v50 in 93-97 % of them (the binomial
// standard deviation of the count at 95 % is 1.1 %, so a correct method lands inside with
// probability 0.9).
#include <catch2/catch.hpp>

#include "orchestrator/fitting/case_groups.hpp"
#include "orchestrator/fitting/logistic_models.hpp"
#include "tests/fitting/synthetic_study.hpp"

namespace aerobreak {

TEST_CASE("The 95 % profile-likelihood interval of v50 covers the truth in 93-97 % of synthetic studies",
          "[fitting][coverage]") {
  const synthetic::LogisticLaw law{0.05, 3.0};
  // Eight speeds from 0.01 to 0.3 (P(break-up) from 0.008 to 0.996), 20 replicates: the default
  // study's grid and replicate count.
  const auto speeds = synthetic::log_speeds(0.01, 0.3, 8);
  synthetic::Uniform uniform(20260516);
  CorrelationRequest request;
  request.speed_axis = "impact_speed";
  request.levels = {0.5, 0.5, 0.5};
  int covered = 0, fitted = 0;
  constexpr int kStudies = 400;
  for (int study = 0; study < kStudies; ++study) {
    const CaseOutcomeTable table = synthetic::draw_study(law, speeds, 20, uniform);
    const auto groups = group_cases(table, request.speed_axis);
    REQUIRE(groups.size() == 1);
    const LogisticFit fit =
        fit_logistic({}, ImpactOutcome::break_up, "impact_speed",
                     speed_rows(table, groups[0].grid_points, ImpactOutcome::break_up, request), request, {});
    REQUIRE(fit.critical.size() == 3);
    const CriticalValue& v50 = fit.critical[0];
    if (fit.common.status == FitStatus::ok) ++fitted;
    REQUIRE(v50.lower);
    REQUIRE(v50.upper);
    if (*v50.lower <= law.v50 && law.v50 <= *v50.upper) ++covered;
  }
  const double coverage = static_cast<double>(covered) / kStudies;
  INFO("covered " << covered << " of " << kStudies << "; " << fitted << " fitted by maximum likelihood");
  CHECK(coverage >= 0.93);
  CHECK(coverage <= 0.97);
}

}  // namespace aerobreak
