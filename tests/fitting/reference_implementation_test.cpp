// The fits against a reference implementation run once on this project's fixture data: R 4.2.2's
// glm (Debian r-base-core) and statsmodels 0.13.5's MNLogit (Debian python3-statsmodels), installed
// for that one run, not by setup.sh. Coefficients, standard errors and interval ends agree to 1e-6
// relative.
//
// The fixture: 20 replicates at eight speeds for two cluster sizes (stick / bounce / break-up
// counts below), 48 single cases against the energy per contact, 24 retained mass fractions (three
// per speed), and four v50 values with their standard errors in log for the power law.
//
// The R script (Rscript reference.R), abridged to what each check uses:
//   v <- c(0.01, 0.02, 0.03, 0.05, 0.08, 0.12, 0.2, 0.3); x <- log(v)
//   glm(cbind(breakA, 20 - breakA) ~ x, family = binomial, control = glm.control(epsilon = 1e-14))
//   # profile-likelihood interval of the dose where P = p: the slope-only model with offset qlogis(p)
//   critical <- function(y, n, x, p) {
//     f <- glm(cbind(y, n - y) ~ x, family = binomial)
//     theta <- (qlogis(p) - coef(f)[1]) / coef(f)[2]
//     prof <- function(t) glm(cbind(y, n - y) ~ 0 + I(x - t), offset = rep(qlogis(p), length(x)),
//                             family = binomial, control = glm.control(epsilon = 1e-14, maxit = 100))$deviance -
//                         deviance(f) - qchisq(0.95, 1)
//     lo <- uniroot(prof, c(theta - 3, theta), tol = 1e-13)$root
//     hi <- uniroot(prof, c(theta, theta + 3), tol = 1e-13)$root
//     cat(sprintf("p = %.1f: v = %.12g [%.12g, %.12g]\n", p, exp(theta), exp(lo), exp(hi))) }
//   glm(cbind(c(breakA, breakB), 20 - c(breakA, breakB)) ~ rep(x, 2) + log(N), family = binomial)
//   glm(yE ~ log(E), family = binomial)
//   glm(fr ~ log(rep(v, each = 3)), family = quasibinomial)
//   fw <- lm(lv ~ lN + lg, weights = 1 / se^2); sqrt(diag(summary(fw)$cov.unscaled))
// Its output:
//   break-up, N = 32: (Intercept) 5.19597713655170 SE 0.811609705746725; x 2.04348718627862 SE 0.303928095167396
//   p = 0.1: v = 0.026838067435 [0.0172506043956, 0.0372063507954]
//   p = 0.5: v = 0.0786536604255 [0.0633927604558, 0.0979116172279]
//   p = 0.9: v = 0.230508337208 [0.165239469637, 0.367391529157]
//   stick, N = 32: (Intercept) -5.84644773364333 SE 0.877745254292180; x -1.78652727249445 SE 0.271871426109365
//   p = 0.1: v = 0.12968653471 [0.0912985204449, 0.209420891118]
//   p = 0.5: v = 0.0379107395432 [0.0293252030927, 0.0479941496844]
//   p = 0.9: v = 0.0110822929761 [0.00615062425808, 0.0165379458232]
//   break-up pooled, log N: (Intercept) 6.231419790302835 SE 1.144144841333684;
//     rep(x, 2) 1.974162739163768 SE 0.210954716603717; log(N) -0.350161297993368 SE 0.226739531429917
//   break-up vs energy per contact: (Intercept) -4.48122604888272 SE 1.93233608271035;
//     log(E) 6.09674415984278 SE 2.43694847002736
//   p = 0.1: v = 1.45444796835 [0.876560195084, 1.92936070546]
//   p = 0.5: v = 2.08552272989 [1.62370263863, 2.67861719173]
//   p = 0.9: v = 2.99041639958 [2.25433226095, 4.95894924011]
//   retained mass fraction, quasi-binomial: (Intercept) -4.34855144287107 SE 0.400036174503733;
//     log(v) -1.53249511693183 SE 0.136579104558209; dispersion 0.0509106431995322
//   power law: coefficients -1.839206172311440 0.155501424409856 0.272859429117981
//     standard errors from (X'WX)^-1: 0.1881978738357903 0.0424370218140313 0.0234189103099331 (chi2/df 0.185)
// The per-condition pooled models: the same counts on two walls (axis /wall/adhesive), the adhesive
// one as above and on the other the sizes' counts swapped; each wall's model pools along N alone:
//   N <- rep(c(32, 128), each = 8); ctl <- glm.control(epsilon = 1e-14, maxit = 100)
//   glm(cbind(c(breakA, breakB), 20 - c(breakA, breakB)) ~ rep(x, 2) + log(N), family = binomial, control = ctl)
//   glm(cbind(c(breakB, breakA), 20 - c(breakB, breakA)) ~ rep(x, 2) + log(N), family = binomial, control = ctl)
//   glm(cbind(c(stickB, stickA), 20 - c(stickB, stickA)) ~ rep(x, 2) + log(N), family = binomial, control = ctl)
// Its output (R 4.2.2):
//   wall 1 break-up 6.23141979030283 SE 1.14414484133368; 1.97416273916377 SE 0.210954716603717;
//     -0.350161297993368 SE 0.226739531429917
//   wall 2 break-up 3.31885999295906 SE 1.03153284043332; 1.97416273916377 SE 0.210954716603715;
//     0.350161297993369 SE 0.226739531429916
//   wall 2 stick -3.49733718184593 SE 0.996334947775349; -1.7372883854707 SE 0.185345276311066;
//     -0.452416041348993 SE 0.219089615173936
// (Pooled over both walls, as the pooled model once was, the break-up curve would have been
// 4.7248045253736 + 1.95351957366026 x + 0 log N: a mixture that describes neither wall.)
// The statsmodels script (python3 mnlogit.py): the N = 32 counts expanded to one row per case,
//   sm.MNLogit(y, sm.add_constant(log v)).fit(method="newton", tol=1e-14, maxiter=100)
// Its output (columns: bounce, break-up against stick; rows: constant, log v):
//   params [[2.85876820286243 7.41981154519488] [1.075080700523205 2.591877743639578]]
//   bse    [[1.015096796144351 1.088904018811923] [0.301447085273599 0.373832375129629]]
//   llf -112.66993834996097
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "orchestrator/fitting/case_groups.hpp"
#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/fitting/logistic_models.hpp"
#include "orchestrator/fitting/multinomial_logit.hpp"
#include "orchestrator/fitting/secondary_fits.hpp"

namespace aerobreak {
namespace {

constexpr double kRelative = 1e-6;
const std::vector<double> kSpeeds{0.01, 0.02, 0.03, 0.05, 0.08, 0.12, 0.2, 0.3};

struct Counts {
  std::vector<int> stick, bounce, break_up;
};
const Counts kSmall{{18, 15, 12, 8, 5, 2, 1, 0}, {2, 4, 5, 6, 5, 4, 2, 1}, {0, 1, 3, 6, 10, 14, 17, 19}};
const Counts kLarge{{19, 17, 14, 11, 7, 4, 2, 1}, {1, 2, 4, 5, 5, 4, 3, 1}, {0, 1, 2, 4, 8, 12, 15, 18}};

void add_group(CaseOutcomeTable& table, double primaries, const Counts& counts) {
  for (std::size_t s = 0; s < kSpeeds.size(); ++s) {
    table.grid_points.push_back({{"impact_speed", kSpeeds[s]}, {"primaries", primaries}});
    const std::pair<ImpactOutcome, int> outcomes[] = {{ImpactOutcome::stick, counts.stick[s]},
                                                      {ImpactOutcome::bounce, counts.bounce[s]},
                                                      {ImpactOutcome::break_up, counts.break_up[s]}};
    for (const auto& [outcome, n] : outcomes)
      for (int i = 0; i < n; ++i) {
        CaseOutcome c;
        c.grid_point = table.grid_points.size() - 1;
        c.outcome = outcome;
        table.cases.push_back(c);
      }
  }
}

void add_group(CaseOutcomeTable& table, nlohmann::ordered_json axes, const Counts& counts) {
  const std::size_t first = table.grid_points.size();
  add_group(table, axes.at("primaries").get<double>(), counts);
  for (std::size_t g = first; g < table.grid_points.size(); ++g) table.grid_points[g].update(axes);
}

// The fixture's counts on two walls: the adhesive wall as fixture_study, the other with the sizes'
// counts swapped.
CaseOutcomeTable two_wall_study() {
  CaseOutcomeTable table;
  table.axes = {"impact_speed", "/wall/adhesive", "primaries"};
  add_group(table, {{"/wall/adhesive", true}, {"primaries", 32}}, kSmall);
  add_group(table, {{"/wall/adhesive", true}, {"primaries", 128}}, kLarge);
  add_group(table, {{"/wall/adhesive", false}, {"primaries", 32}}, kLarge);
  add_group(table, {{"/wall/adhesive", false}, {"primaries", 128}}, kSmall);
  return table;
}

CaseOutcomeTable fixture_study() {
  CaseOutcomeTable table;
  table.axes = {"impact_speed", "primaries"};
  add_group(table, 32, kSmall);
  add_group(table, 128, kLarge);
  return table;
}

CorrelationRequest speed_request() {
  CorrelationRequest request;
  request.speed_axis = "impact_speed";
  return request;
}

void check_estimate(const FitCommon& fit, Eigen::Index j, double estimate, double standard_error) {
  CHECK(fit.coefficients[j] == Approx(estimate).epsilon(kRelative));
  CHECK(std::sqrt(fit.covariance(j, j)) == Approx(standard_error).epsilon(kRelative));
}

void check_critical(const CriticalValue& value, double estimate, double lower, double upper) {
  REQUIRE(value.estimate);
  REQUIRE(value.lower);
  REQUIRE(value.upper);
  CHECK(*value.estimate == Approx(estimate).epsilon(kRelative));
  CHECK(*value.lower == Approx(lower).epsilon(kRelative));
  CHECK(*value.upper == Approx(upper).epsilon(kRelative));
}

LogisticFit group_fit(const CaseOutcomeTable& table, ImpactOutcome response) {
  const auto groups = group_cases(table, "impact_speed");
  const auto request = speed_request();
  return fit_logistic({}, response, "impact_speed", speed_rows(table, groups[0].grid_points, response, request),
                      request, {});
}

}  // namespace

TEST_CASE("Per-group logistic fits and profile-likelihood critical speeds agree with R", "[fitting][reference]") {
  const CaseOutcomeTable table = fixture_study();
  const LogisticFit break_up = group_fit(table, ImpactOutcome::break_up);
  REQUIRE(break_up.common.status == FitStatus::ok);
  check_estimate(break_up.common, 0, 5.19597713655170, 0.811609705746725);
  check_estimate(break_up.common, 1, 2.04348718627862, 0.303928095167396);
  check_critical(break_up.critical[0], 0.026838067435, 0.0172506043956, 0.0372063507954);
  check_critical(break_up.critical[1], 0.0786536604255, 0.0633927604558, 0.0979116172279);
  check_critical(break_up.critical[2], 0.230508337208, 0.165239469637, 0.367391529157);

  const LogisticFit stick = group_fit(table, ImpactOutcome::stick);
  check_estimate(stick.common, 0, -5.84644773364333, 0.877745254292180);
  check_estimate(stick.common, 1, -1.78652727249445, 0.271871426109365);
  check_critical(stick.critical[0], 0.12968653471, 0.0912985204449, 0.209420891118);
  check_critical(stick.critical[1], 0.0379107395432, 0.0293252030927, 0.0479941496844);
  check_critical(stick.critical[2], 0.0110822929761, 0.00615062425808, 0.0165379458232);
}

TEST_CASE("The pooled model with log N as covariate agrees with R", "[fitting][reference]") {
  const CaseOutcomeTable table = fixture_study();
  CorrelationRequest request = speed_request();
  request.covariates = {{"primaries", true}};
  std::vector<std::size_t> all(table.grid_points.size());
  std::iota(all.begin(), all.end(), 0);
  const LogisticFit pooled = fit_logistic({}, ImpactOutcome::break_up, "impact_speed",
                                          speed_rows(table, all, ImpactOutcome::break_up, request), request, {});
  check_estimate(pooled.common, 0, 6.231419790302835, 1.144144841333684);
  check_estimate(pooled.common, 1, 1.974162739163768, 0.210954716603717);
  check_estimate(pooled.common, 2, -0.350161297993368, 0.226739531429917);
  CHECK(pooled.common.groups == 16);
  CHECK(pooled.common.cases == 320);
}

TEST_CASE("Pooled models pool along N only: one per wall, each R's glm on that wall's cases", "[fitting][reference]") {
  CorrelationRequest request = speed_request();
  request.size_axis = "primaries";
  request.covariates = {{"primaries", true}};
  const CorrelationSet set = compute_correlations(two_wall_study(), request, {});
  const auto named = [&set](const std::string& name) -> const LogisticFit& {
    const auto found = std::find_if(set.logistic.begin(), set.logistic.end(),
                                    [&](const LogisticFit& f) { return f.common.name == name; });
    REQUIRE(found != set.logistic.end());
    return *found;
  };
  const LogisticFit& adhesive = named("break-up.speed.pooled.c1");
  CHECK(adhesive.common.group == nlohmann::ordered_json{{"/wall/adhesive", true}});
  check_estimate(adhesive.common, 0, 6.23141979030283, 1.14414484133368);
  check_estimate(adhesive.common, 1, 1.97416273916377, 0.210954716603717);
  check_estimate(adhesive.common, 2, -0.350161297993368, 0.226739531429917);
  const LogisticFit& other = named("break-up.speed.pooled.c2");
  CHECK(other.common.group == nlohmann::ordered_json{{"/wall/adhesive", false}});
  CHECK(other.common.cases == 320);
  check_estimate(other.common, 0, 3.31885999295906, 1.03153284043332);
  check_estimate(other.common, 1, 1.97416273916377, 0.210954716603715);
  check_estimate(other.common, 2, 0.350161297993369, 0.226739531429916);
  const LogisticFit& stick = named("stick.speed.pooled.c2");
  check_estimate(stick.common, 0, -3.49733718184593, 0.996334947775349);
  check_estimate(stick.common, 1, -1.7372883854707, 0.185345276311066);
  check_estimate(stick.common, 2, -0.452416041348993, 0.219089615173936);
  // No fit mixes the walls: every pooled model and scaling law names its wall.
  for (const LogisticFit& fit : set.logistic) CHECK(fit.common.group.contains("/wall/adhesive"));
  REQUIRE(set.scaling.size() == 6);  // stick, bounce, break-up x two walls
  for (const ScalingFit& fit : set.scaling) {
    CHECK(fit.common.group.contains("/wall/adhesive"));
    CHECK(fit.common.cases == 320);
    // P(bounce) never reaches 0.5 in these counts: no v50, no law, and the fit says why.
    CHECK(fit.axes ==
          (fit.response == ImpactOutcome::bounce ? std::vector<std::string>{} : std::vector<std::string>{"primaries"}));
    CHECK(fit.common.status == (fit.response == ImpactOutcome::bounce ? FitStatus::insufficient_data : FitStatus::ok));
  }
}

TEST_CASE("The energy-per-contact fit of single cases agrees with R", "[fitting][reference]") {
  const std::vector<double> energy{0.3,    0.327,   0.3564,  0.3885,  0.4235,  0.4616,  0.5031, 0.5484, 0.5978, 0.6516,
                                   0.7102, 0.7741,  0.8438,  0.9197,  1.0025,  1.0927,  1.1911, 1.2983, 1.4151, 1.5425,
                                   1.6813, 1.8326,  1.9976,  2.1774,  2.3733,  2.5869,  2.8197, 3.0735, 3.3501, 3.6517,
                                   3.9803, 4.3385,  4.729,   5.1546,  5.6185,  6.1242,  6.6754, 7.2762, 7.931,  8.6448,
                                   9.4228, 10.2709, 11.1953, 12.2028, 13.3011, 14.4982, 15.803, 17.2253};
  const std::vector<int> broke{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1,
                               1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  CaseOutcomeTable table;
  table.axes = {"impact_speed"};
  table.grid_points.push_back({{"impact_speed", 0.1}});
  for (std::size_t i = 0; i < energy.size(); ++i) {
    CaseOutcome c;
    c.outcome = broke[i] ? ImpactOutcome::break_up : ImpactOutcome::stick;
    c.energy_per_contact = energy[i];
    table.cases.push_back(c);
  }
  const auto groups = group_cases(table, "impact_speed");
  const auto request = speed_request();
  const LogisticFit fit =
      fit_logistic({}, ImpactOutcome::break_up, "energy_per_contact",
                   energy_rows(table, groups[0].cases, ImpactOutcome::break_up, request), request, {});
  check_estimate(fit.common, 0, -4.48122604888272, 1.93233608271035);
  check_estimate(fit.common, 1, 6.09674415984278, 2.43694847002736);
  check_critical(fit.critical[0], 1.45444796835, 0.876560195084, 1.92936070546);
  check_critical(fit.critical[1], 2.08552272989, 1.62370263863, 2.67861719173);
  check_critical(fit.critical[2], 2.99041639958, 2.25433226095, 4.95894924011);
  REQUIRE(fit.common.goodness_of_fit.size() == 1);
  CHECK(fit.common.goodness_of_fit[0].statistic == "hosmer-lemeshow");
}

TEST_CASE("The quasi-binomial retained-fraction fit agrees with R", "[fitting][reference]") {
  const std::vector<double> fractions{0.928, 0.871, 0.976, 0.834, 0.721, 0.905, 0.792, 0.814,
                                      0.854, 0.597, 0.577, 0.464, 0.443, 0.345, 0.358, 0.16,
                                      0.184, 0.219, 0.244, 0,     0.025, 0.101, 0.198, 0.128};
  CaseOutcomeTable table;
  table.axes = {"impact_speed"};
  for (std::size_t s = 0; s < kSpeeds.size(); ++s) {
    table.grid_points.push_back({{"impact_speed", kSpeeds[s]}});
    for (std::size_t r = 0; r < 3; ++r) {
      CaseOutcome c;
      c.grid_point = s;
      c.outcome = ImpactOutcome::break_up;
      c.retained_mass_fraction = fractions[3 * s + r];
      table.cases.push_back(c);
    }
  }
  const auto fits = fit_retained_fractions(table, group_cases(table, "impact_speed"), speed_request());
  REQUIRE(fits.size() == 1);
  check_estimate(fits[0].common, 0, -4.34855144287107, 0.400036174503733);
  check_estimate(fits[0].common, 1, -1.53249511693183, 0.136579104558209);
  CHECK(fits[0].dispersion == Approx(0.0509106431995322).epsilon(kRelative));
}

TEST_CASE("The weighted power law of v50 agrees with R's weighted least squares", "[fitting][reference]") {
  const double v50[] = {0.041, 0.052, 0.078, 0.094}, primaries[] = {32, 128, 32, 128},
               gamma[] = {0.001, 0.001, 0.01, 0.01};
  const double sigma[] = {0.05, 0.06, 0.04, 0.08};  // standard errors of log v50
  std::vector<LogisticFit> groups(4);
  for (std::size_t g = 0; g < 4; ++g) {
    groups[g].dose = "impact_speed";
    groups[g].common.group = {{"primaries", primaries[g]}, {"gamma_over_kn", gamma[g]}};
    const double half = kZ95 * sigma[g];  // an interval symmetric in log with that standard error
    groups[g].critical.push_back({0.5, {}, v50[g], v50[g] * std::exp(-half), v50[g] * std::exp(half)});
  }
  CorrelationRequest request = speed_request();
  request.covariates = {{"primaries", true}, {"gamma_over_kn", true}};  // the axes the law models
  const auto fits = fit_scaling_laws(groups, {{"c1", nlohmann::ordered_json::object(), {}, {}}}, request);
  REQUIRE(fits.size() == 1);
  REQUIRE(fits[0].common.status == FitStatus::ok);
  CHECK(fits[0].axes == std::vector<std::string>{"primaries", "gamma_over_kn"});
  check_estimate(fits[0].common, 0, -1.839206172311440, 0.1881978738357903);
  check_estimate(fits[0].common, 1, 0.155501424409856, 0.0424370218140313);
  check_estimate(fits[0].common, 2, 0.272859429117981, 0.0234189103099331);
  CHECK(fits[0].scale_factor == 1.0);
}

TEST_CASE("The multinomial logit agrees with statsmodels' MNLogit", "[fitting][reference]") {
  std::vector<std::vector<double>> counts;
  for (std::size_t s = 0; s < kSpeeds.size(); ++s)
    counts.push_back({double(kSmall.stick[s]), double(kSmall.bounce[s]), double(kSmall.break_up[s])});
  const MultinomialFit fit = fit_multinomial(kSpeeds, counts);
  REQUIRE(fit.common.status == FitStatus::ok);
  check_estimate(fit.common, 0, 2.85876820286243, 1.015096796144351);
  check_estimate(fit.common, 1, 1.075080700523205, 0.301447085273599);
  check_estimate(fit.common, 2, 7.41981154519488, 1.088904018811923);
  check_estimate(fit.common, 3, 2.591877743639578, 0.373832375129629);
  CHECK(*fit.common.log_likelihood == Approx(-112.66993834996097).epsilon(kRelative));
}

}  // namespace aerobreak
