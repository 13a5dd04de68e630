// The binomial GLM (IRLS) against a published textbook fit, Firth's estimate against its closed
// form, and separation found on data built to have it (and not found where it is absent).
#include <catch2/catch.hpp>

#include <cmath>

#include "orchestrator/fitting/binomial_glm.hpp"
#include "orchestrator/fitting/separation.hpp"

namespace aerobreak {
namespace {

BinomialData dose_response(const std::vector<double>& dose, const std::vector<double>& trials,
                           const std::vector<double>& successes) {
  BinomialData data;
  const auto n = static_cast<Eigen::Index>(dose.size());
  data.design.resize(n, 2);
  data.design.col(0).setOnes();
  data.design.col(1) = Eigen::Map<const Eigen::VectorXd>(dose.data(), n);
  data.trials = Eigen::Map<const Eigen::VectorXd>(trials.data(), n);
  data.successes = Eigen::Map<const Eigen::VectorXd>(successes.data(), n);
  return data;
}

double standard_error(const GlmFit& fit, Eigen::Index j) { return std::sqrt(fit.covariance(j, j)); }

}  // namespace

// Bliss (Ann. Appl. Biol. 22 (1935) 134), beetles killed after five hours' exposure to gaseous
// carbon disulphide, as analysed in Dobson & Barnett, An Introduction to Generalized Linear Models
// (3rd ed., sec. 7.3.1, table 7.3): logit model b1 = -60.72 (SE 5.18), b2 = 34.27 (SE 2.91) in
// x = log10 dose. The data, dose x, beetles n, killed y, as in the book (the same numbers appear in
// public R scripts of this example).
TEST_CASE("Logistic regression reproduces Dobson & Barnett's fit of Bliss's beetle data", "[fitting][glm]") {
  const BinomialData bliss = dose_response({1.6907, 1.7242, 1.7552, 1.7842, 1.8113, 1.8369, 1.8610, 1.8839},
                                           {59, 60, 62, 56, 63, 59, 62, 60}, {6, 13, 18, 28, 52, 53, 61, 60});
  const GlmFit fit = fit_binomial(bliss);
  REQUIRE(fit.converged);
  CHECK(fit.coefficients[0] == Approx(-60.72).epsilon(1e-3));
  CHECK(fit.coefficients[1] == Approx(34.27).epsilon(1e-3));
  CHECK(standard_error(fit, 0) == Approx(5.18).epsilon(1e-3));
  CHECK(standard_error(fit, 1) == Approx(2.91).epsilon(1e-3));
  // The book's deviance for this model: D = 11.23 on 6 degrees of freedom.
  CHECK(fit.deviance == Approx(11.23).epsilon(1e-3));
  CHECK_FALSE(find_separation(bliss, fit));
}

// Firth's estimate of a single proportion is the posterior mode under the Jeffreys prior:
// logit((k + 1/2) / (n + 1)) (Firth 1993, sec. 3.1) -- finite for k = 0, where ML is -infinity.
TEST_CASE("Firth's estimate of an intercept-only model is logit((k + 1/2)/(n + 1))", "[fitting][glm]") {
  for (const double k : {0.0, 3.0, 10.0}) {
    BinomialData data;
    data.design = Eigen::MatrixXd::Ones(1, 1);
    data.trials = Eigen::VectorXd::Constant(1, 10.0);
    data.successes = Eigen::VectorXd::Constant(1, k);
    GlmOptions options;
    options.penalty = Penalty::firth;
    const GlmFit fit = fit_binomial(data, options);
    REQUIRE(fit.converged);
    CHECK(fit.coefficients[0] == Approx(std::log((k + 0.5) / (10.0 - k + 0.5))).epsilon(1e-9));
  }
}

TEST_CASE("Complete separation is found, with every row perfectly predicted", "[fitting][separation]") {
  // All stick (0) below 0.3, all break-up above: no overlap.
  const BinomialData data = dose_response({0.1, 0.2, 0.3, 0.4, 0.5, 0.6}, {5, 5, 5, 5, 5, 5}, {0, 0, 0, 5, 5, 5});
  const GlmFit fit = fit_binomial(data);
  CHECK_FALSE(fit.converged);
  const auto separation = find_separation(data, fit);
  REQUIRE(separation);
  CHECK(separation->complete);
  CHECK(separation->perfectly_predicted.size() == 6);
  // The separating plane lies between 0.3 and 0.4.
  const double crossing = -separation->direction[0] / separation->direction[1];
  CHECK(crossing > 0.3);
  CHECK(crossing < 0.4);
  // Firth's fit is finite and puts the 50 % point between the two groups.
  GlmOptions options;
  options.penalty = Penalty::firth;
  const GlmFit firth = fit_binomial(data, options);
  REQUIRE(firth.converged);
  const double midpoint = -firth.coefficients[0] / firth.coefficients[1];
  CHECK(midpoint == Approx(0.35).margin(0.01));
}

TEST_CASE("Quasi-complete separation: the mixed row lies on the plane", "[fitting][separation]") {
  // Mixed outcomes only at 0.3; all 0 below, all 1 above.
  const BinomialData data = dose_response({0.1, 0.2, 0.3, 0.4, 0.5}, {5, 5, 5, 5, 5}, {0, 0, 2, 5, 5});
  const GlmFit fit = fit_binomial(data);
  const auto separation = find_separation(data, fit);
  REQUIRE(separation);
  CHECK_FALSE(separation->complete);
  CHECK(separation->perfectly_predicted == std::vector<std::size_t>{0, 1, 3, 4});
}

TEST_CASE("A steep but overlapping transition is not taken for separation", "[fitting][separation]") {
  const BinomialData data = dose_response({0.1, 0.2, 0.3, 0.4, 0.5}, {20, 20, 20, 20, 20}, {0, 1, 10, 19, 20});
  const GlmFit fit = fit_binomial(data);
  CHECK(fit.converged);
  CHECK_FALSE(find_separation(data, fit));
}

}  // namespace aerobreak
