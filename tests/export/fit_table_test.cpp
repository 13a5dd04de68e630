// Table (b) (docs/EXPORT.md, "kind=fit") at sizes the study did not run: the rows come from the
// logistic fit pooled over the study's sizes (logit P = b0 + b1 ln v + b2 ln N), checked against a
// hand computation from its coefficients and covariance, against R's glm, through `aerobreak
// export`, and by the coverage of its 95 % band on synthetic studies drawn from a known law.
#include <catch2/catch.hpp>

#include <cmath>

#include "orchestrator/export/equivalent_diameters.hpp"
#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/fitting/case_groups.hpp"
#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/fitting/logistic_models.hpp"
#include "orchestrator/fitting/proportion.hpp"
#include "orchestrator/app/study_fits.hpp"
#include "tests/export/pooled_size_study.hpp"
#include "tests/fitting/synthetic_study.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {
namespace {

constexpr double kZ = 1.959963984540054;  // the normal 0.975 quantile

struct PooledFixture {
  ScratchDirectory directory{"fit_table"};
  Store store{directory.path() / "store.sqlite"};
  std::int64_t study = fill_pooled_study(store);
  CorrelationSet fits =
      study_correlations(store, *store.study(study), correlation_request(*store.study(study), std::nullopt));

  LookupTable table(ExportRequest request) {
    request.kind = TableKind::fit;
    return study_lookup_table(store, study, request, &fits);
  }
};

const LogisticFit& fit_named(const std::vector<LogisticFit>& fits, const std::string& name) {
  for (const auto& fit : fits)
    if (fit.common.name == name) return fit;
  FAIL("no fit " << name);
  return fits.front();
}

double at(const LookupTable& table, const char* column, std::size_t row) {
  REQUIRE(table.find(column));
  return table.find(column)->values[row];
}

struct Band {
  double p, lower, upper;
};

// P = 1 / (1 + exp(-eta)) and eta +- z sqrt(x' C x) transformed, x = (1, ln v[, ln N]).
Band band_by_hand(const FitCommon& fit, double speed, double size) {
  std::vector<double> x{1.0, std::log(speed)};
  if (fit.coefficients.size() == 3) x.push_back(std::log(size));
  double eta = 0.0, variance = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    eta += fit.coefficients[static_cast<Eigen::Index>(i)] * x[i];
    for (std::size_t j = 0; j < x.size(); ++j)
      variance += x[i] * fit.covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) * x[j];
  }
  const auto p = [](double e) { return 1.0 / (1.0 + std::exp(-e)); };
  return {p(eta), p(eta - kZ * std::sqrt(variance)), p(eta + kZ * std::sqrt(variance))};
}

void check_row(const LookupTable& table, std::size_t row, const char* outcome, const Band& expected) {
  const std::string name = std::string("p_") + outcome;
  CHECK(at(table, (name + "_status").c_str(), row) == 0.0);  // fitted by maximum likelihood
  CHECK(at(table, name.c_str(), row) == Approx(expected.p).epsilon(1e-9));
  CHECK(at(table, (name + "_lo").c_str(), row) == Approx(expected.lower).epsilon(1e-9));
  CHECK(at(table, (name + "_hi").c_str(), row) == Approx(expected.upper).epsilon(1e-9));
}

}  // namespace

TEST_CASE("Fit table at sizes not run: P and its 95 % band equal a hand computation from the pooled fit",
          "[export][fit]") {
  PooledFixture fixture;
  const auto& stick = fit_named(fixture.fits.logistic, "stick.speed.pooled.c1").common;
  const auto& break_up = fit_named(fixture.fits.logistic, "break-up.speed.pooled.c1").common;
  REQUIRE(stick.status == FitStatus::ok);
  REQUIRE(break_up.status == FitStatus::ok);
  ExportRequest request;
  request.speeds = {0.015, 0.05, 0.25};
  request.sizes = {512, 64, 32, 16};
  const auto table = fixture.table(request);
  REQUIRE(table.rows() == 12);  // sizes ascending, then the speeds as asked
  const std::vector<double> sizes{16, 32, 64, 512};
  for (std::size_t row = 0; row < table.rows(); ++row) {
    const double size = sizes[row / 3], speed = request.speeds[row % 3];
    INFO("N = " << size << ", v = " << speed);
    CHECK(at(table, "primaries", row) == size);
    CHECK(at(table, "impact_speed", row) == speed);
    CHECK(at(table, "d_ve", row) == Approx(std::cbrt(size)).epsilon(1e-12));
    if (size == 32) {  // run: the size's own fit (group g1 is N = 32)
      CHECK(at(table, "model", row) == 0.0);
      check_row(table, row, "bounce",
                band_by_hand(fit_named(fixture.fits.logistic, "bounce.speed.g1").common, speed, size));
      check_row(table, row, "stick",
                band_by_hand(fit_named(fixture.fits.logistic, "stick.speed.g1").common, speed, size));
      check_row(table, row, "break_up",
                band_by_hand(fit_named(fixture.fits.logistic, "break-up.speed.g1").common, speed, size));
      CHECK(at(table, "inside_validity", row) == 1.0);
      continue;
    }
    CHECK(at(table, "model", row) == 1.0);
    check_row(table, row, "stick", band_by_hand(stick, speed, size));
    check_row(table, row, "bounce",
              band_by_hand(fit_named(fixture.fits.logistic, "bounce.speed.pooled.c1").common, speed, size));
    check_row(table, row, "break_up", band_by_hand(break_up, speed, size));
    // Between the sizes run (32 and 128): interpolation in ln N, inside the box; 16 and 512 outside.
    CHECK(at(table, "inside_validity", row) == (size == 64 ? 1.0 : 0.0));
  }
  CHECK(table.metadata.at("fit_models").at("pooled_ln_n").get<std::string>().find("b2 ln N") != std::string::npos);
  CHECK(table.metadata.at("validity").at("primaries") ==
        nlohmann::ordered_json::array({32.0, 128.0}));  // run, not tabulated
  CHECK(table.metadata.at("validity").at("impact_speed") == nlohmann::ordered_json::array({0.01, 0.3}));
}

// R 4.2.2 (Debian r-base-core) on the same counts, from tests/fitting/reference_implementation_test.cpp:
//   glm(cbind(c(breakA, breakB), 20 - c(breakA, breakB)) ~ rep(x, 2) + log(N), family = binomial)
//   (Intercept) 6.231419790302835 SE 1.144144841333684; rep(x, 2) 1.974162739163768 SE 0.210954716603717;
//   log(N) -0.350161297993368 SE 0.226739531429917
// That test checks the pooled model against these numbers; this one checks that the exported rows
// are that model, fitted from the store: the correlations' break-up.speed.pooled.c1 (the study has
// no axis besides speed and N: one condition) and, at N = 64, P = logistic(R's linear predictor).
TEST_CASE("Fit table at sizes not run: the rows are the pooled model R's glm reproduces", "[export][fit][reference]") {
  PooledFixture fixture;
  const auto& exported = fit_named(fixture.fits.logistic, "break-up.speed.pooled.c1").common;
  REQUIRE(exported.coefficients.size() == 3);
  const double r_estimate[] = {6.231419790302835, 1.974162739163768, -0.350161297993368};
  for (Eigen::Index j = 0; j < 3; ++j) CHECK(exported.coefficients[j] == Approx(r_estimate[j]).epsilon(1e-6));
  const double r_se[] = {1.144144841333684, 0.210954716603717, 0.226739531429917};
  for (Eigen::Index j = 0; j < 3; ++j) CHECK(std::sqrt(exported.covariance(j, j)) == Approx(r_se[j]).epsilon(1e-6));
  ExportRequest request;
  request.speeds = {0.02, 0.08, 0.2};
  request.sizes = {64};
  const auto table = fixture.table(request);
  REQUIRE(table.rows() == 3);
  for (std::size_t row = 0; row < 3; ++row) {
    const double eta =
        6.231419790302835 + 1.974162739163768 * std::log(request.speeds[row]) - 0.350161297993368 * std::log(64.0);
    CHECK(at(table, "p_break_up", row) == Approx(1.0 / (1.0 + std::exp(-eta))).epsilon(1e-6));
  }
}

namespace {

// The counts of pooled_size_study.hpp as an outcome table, for two walls: the non-adhesive one with
// the two sizes' counts swapped, so that its curves differ.
CaseOutcomeTable two_walls() {
  CaseOutcomeTable table;
  table.axes = {"impact_speed", "/wall/adhesive", "primaries"};
  for (const bool adhesive : {true, false})
    for (const int size : kPooledSizes)
      for (std::size_t s = 0; s < kPooledSpeeds.size(); ++s) {
        table.grid_points.push_back(
            {{"impact_speed", kPooledSpeeds[s]}, {"/wall/adhesive", adhesive}, {"primaries", size}});
        for (int r = 0; r < kPooledReplicates; ++r) {
          const auto fragments = pooled_fragments(adhesive ? size : 160 - size, s, r);
          const std::string outcome = outcome_of(fragments, adhesive ? size : 160 - size);
          CaseOutcome c;
          c.grid_point = table.grid_points.size() - 1;
          c.outcome = outcome == "stick"    ? ImpactOutcome::stick
                      : outcome == "bounce" ? ImpactOutcome::bounce
                                            : ImpactOutcome::break_up;
          table.cases.push_back(c);
        }
      }
  return table;
}

}  // namespace

TEST_CASE("Fit table at sizes not run: one pooled fit per condition of the other axes (a boolean wall axis)",
          "[export][fit]") {
  const CaseOutcomeTable outcomes = two_walls();
  CorrelationSet set;
  set.request.speed_axis = "impact_speed";
  set.request.size_axis = "primaries";
  set.request.covariates = {{"primaries", true}};
  set.logistic = fit_logistic_models(outcomes, group_cases(outcomes, "impact_speed"), set.request);
  ExportRequest request;
  request.kind = TableKind::fit;
  request.sizes = {48};  // not 64: between 32 and 128 in ln N the swapped counts give the same P there
  request.speeds = {0.05};
  const auto table = fit_table(set, request, 1.0);
  REQUIRE(table.rows() == 2);
  CHECK(table.find("wall_adhesive")->values == std::vector<double>{1.0, 0.0});
  for (std::size_t row = 0; row < 2; ++row) {
    const auto& pooled = fit_named(set.logistic, row == 0 ? "break-up.speed.pooled.c1" : "break-up.speed.pooled.c2");
    CHECK(pooled.common.group == nlohmann::ordered_json{{"/wall/adhesive", row == 0}});
    CHECK(at(table, "p_break_up", row) == Approx(band_by_hand(pooled.common, 0.05, 48).p).epsilon(1e-9));
  }
  CHECK(at(table, "p_break_up", 0) != Approx(at(table, "p_break_up", 1)).epsilon(1e-3));
}

// The two-wall study of export_study.hpp: nothing sticks on the wall without adhesion (12 determined
// results per size there), so its stick fits have no transition.
TEST_CASE("Fit table: every outcome with its band and status: no transition gives the observed 0 with its Wilson band",
          "[export][fit]") {
  ScratchDirectory directory("fit_table_walls");
  Store store(directory.path() / "store.sqlite");
  const auto study = fill_wall_study(store);
  const auto fits =
      study_correlations(store, *store.study(study), correlation_request(*store.study(study), std::nullopt));
  ExportRequest request;
  request.kind = TableKind::fit;
  request.speeds = {0.01, 0.02, 0.05};
  const auto table = study_lookup_table(store, study, request, &fits);
  REQUIRE(table.rows() == 12);  // 2 sizes x 2 walls x 3 speeds
  const auto no_stick = *wilson_interval(0, 12);
  std::size_t without_adhesion = 0;
  for (std::size_t row = 0; row < table.rows(); ++row)
    for (const std::string outcome : {"p_stick", "p_bounce", "p_break_up"}) {
      INFO("row " << row << " " << outcome);
      const double status = at(table, (outcome + "_status").c_str(), row);
      const double p = at(table, outcome.c_str(), row), lo = at(table, (outcome + "_lo").c_str(), row),
                   hi = at(table, (outcome + "_hi").c_str(), row);
      REQUIRE((status == 0.0 || status == 1.0 || status == 2.0 || status == 3.0));
      if (status == 3.0) {
        CHECK(std::isnan(p));
        continue;
      }
      CHECK(lo <= p);
      CHECK(p <= hi);
      if (status == 2.0) CHECK((p == 0.0 || p == 1.0));
      if (outcome == "p_stick" && at(table, "wall_adhesive", row) == 0.0) {
        ++without_adhesion;
        CHECK(status == 2.0);
        CHECK(p == 0.0);
        CHECK(lo == 0.0);
        CHECK(hi == Approx(no_stick.upper).epsilon(1e-12));
      }
    }
  CHECK(without_adhesion == 6);
  CHECK(table.metadata.at("fit_models").at("status").get<std::string>().find("2 = no transition") != std::string::npos);
}

TEST_CASE("Fit table: strict refuses a size outside the sizes run, naming it and the range (aerobreak export)",
          "[export][fit]") {
  PooledFixture fixture;
  const std::string command = std::string(AEROBREAK_BINARY) + " export --store " +
                              fixture.directory.file("store.sqlite") + " --kind fit --format csv -o -";
  const auto inside = run_command(command + " --speeds 0.05 --sizes 64 --strict true", true);
  REQUIRE(inside.exit_code == 0);
  CHECK(inside.text.find("pooled_ln_n") != std::string::npos);
  const auto refused = run_command(command + " --speeds 0.05 --sizes 512 --strict true");
  INFO(refused.text);
  CHECK(refused.exit_code == 2);
  CHECK(refused.text.find("[parameter sizes]") != std::string::npos);
  CHECK(refused.text.find("from 3.200000000e+01 to 1.280000000e+02") != std::string::npos);
  CHECK(run_command(command + " --speeds 0.05 --sizes 512", true).exit_code == 0);  // not strict: flagged, not refused
  const auto too_fast = run_command(command + " --sizes 64 --speeds 1 --strict true");
  CHECK(too_fast.exit_code == 2);
  CHECK(too_fast.text.find("[parameter speeds]") != std::string::npos);
}

TEST_CASE("Fit table: a size not run is refused with the reason when no pooled fit can be made", "[export][fit]") {
  PooledFixture fixture;
  CorrelationSet without = fixture.fits;
  std::erase_if(without.logistic,
                [](const LogisticFit& fit) { return !fit.covariates.empty(); });  // as for a study of one size
  ExportRequest request;
  request.kind = TableKind::fit;
  request.sizes = {64};
  try {
    study_lookup_table(fixture.store, fixture.study, request, &without);
    FAIL("a size without a fit was not refused");
  } catch (const ExportError& error) {
    CHECK(error.status == 422);
    CHECK(error.field == "sizes");
    CHECK(std::string(error.what()).find("does not sweep the cluster size") != std::string::npos);
  }
  without = fixture.fits;
  for (auto& fit : without.logistic)
    if (!fit.covariates.empty()) fit.common.status = FitStatus::separation;
  try {
    study_lookup_table(fixture.store, fixture.study, request, &without);
    FAIL("a size whose pooled fits are separated was not refused");
  } catch (const ExportError& error) {
    CHECK(error.field == "sizes");
    CHECK(std::string(error.what()).find("separation") != std::string::npos);
  }
}

}  // namespace aerobreak::testing

namespace aerobreak::testing {

// The equivalent diameters of docs/EXPORT.md section 2 at limits with known answers: a sphere (N = 1)
// much smaller than the mean free path settles like a unit-density sphere of rho_p/rho_0 times its
// diameter (Cc proportional to 1/d), a much larger one like sqrt(rho_p/rho_0) times (Cc -> 1); each
// diameter turned back into N gives N.
TEST_CASE("Equivalent diameters: the aerodynamic limits of a sphere, and N back from every diameter",
          "[export][fit][diameters]") {
  const double density = 1725.0;
  CHECK(aerodynamic_diameter(1.0, 1e-9, density) == Approx(1e-9 * density / kUnitDensity).epsilon(2e-3));
  CHECK(aerodynamic_diameter(1.0, 1e-4, density) == Approx(1e-4 * std::sqrt(density / kUnitDensity)).epsilon(2e-3));
  for (const double n : {1.0, 32.0, 4675.0, 1e6}) {
    INFO("N = " << n);
    CHECK(primaries_of_diameter(DiameterType::volume, volume_equivalent_diameter(n)) == Approx(n).epsilon(1e-12));
    CHECK(primaries_of_diameter(DiameterType::mobility, mobility_equivalent_diameter(n)) == Approx(n).epsilon(1e-12));
    CHECK(primaries_of_diameter(DiameterType::aerodynamic, aerodynamic_diameter(n, 2e-8, density), 2e-8, density) ==
          Approx(n).epsilon(1e-9));
  }
  // A fractal aggregate settles slower than its volume-equivalent sphere: d_ae below rho-scaled d_ve.
  CHECK(aerodynamic_diameter(4675.0, 2e-8, density) < 2e-8 * std::cbrt(4675.0) * std::sqrt(density / kUnitDensity));
}

TEST_CASE("Fit table at diameters: each diameter's N, its rows those of that size, aerodynamic only with SI",
          "[export][fit][diameters]") {
  PooledFixture fixture;
  ExportRequest by_diameter;
  by_diameter.speeds = {0.02, 0.1};
  by_diameter.diameters = {5.0, 20.0};  // mobility diameters in d (reduced study): N = 5^2.16 and 20^2.16
  ExportRequest by_size = by_diameter;
  by_size.diameters.clear();
  by_size.sizes = {std::pow(5.0, 2.16), std::pow(20.0, 2.16)};
  const auto diameters = fixture.table(by_diameter), sizes = fixture.table(by_size);
  REQUIRE(diameters.rows() == 4);
  for (const char* column : {"primaries", "p_break_up", "p_break_up_lo", "p_break_up_hi", "inside_validity", "model"})
    for (std::size_t row = 0; row < 4; ++row)
      CHECK(at(diameters, column, row) == Approx(at(sizes, column, row)).epsilon(1e-12));
  CHECK(at(diameters, "d_mob", 0) == Approx(5.0).epsilon(1e-12));
  CHECK(at(diameters, "inside_validity", 0) == 1.0);  // 5^2.16 = 32.3 lies between the sizes run, 32 and 128
  CHECK(at(diameters, "inside_validity", 2) == 0.0);  // 20^2.16 = 646 beyond them: extrapolated, flagged
  by_diameter.diameter_type = DiameterType::aerodynamic;
  CHECK_THROWS_WITH(fixture.table(by_diameter), Catch::Contains("an aerodynamic diameter needs"));
  // With a material (SI): diameters in m; the rows carry all three diameters.
  by_diameter.material = ExportMaterial{{1e10, 0.3, 1725.0, 0.001 * 1e10 * 2e-8 / 2.73}, 2e-8};
  by_diameter.diameters = {2e-7};
  const auto si = fixture.table(by_diameter);
  REQUIRE(si.rows() == 2);
  CHECK(at(si, "d_ae_m", 0) == Approx(2e-7).epsilon(1e-9));
  const double n = at(si, "primaries", 0);
  CHECK(at(si, "d_mob_m", 0) == Approx(2e-8 * mobility_equivalent_diameter(n)).epsilon(1e-12));
  CHECK(at(si, "d_ve_m", 0) == Approx(2e-8 * std::cbrt(n)).epsilon(1e-12));
}

}  // namespace aerobreak::testing
