// The one mean estimate (fitting/mean_estimate.hpp): Student's t quantile against published tables
// and R, the mean with its interval against R's t.test, the streamed form against the two-pass
// one, the ratio estimator against a case derived by hand, and the interval's coverage on synthetic
// data (the Wilson interval: proportion_test.cpp).
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "orchestrator/fitting/mean_estimate.hpp"

namespace aerobreak {
namespace {

// Count, sum and sum of squared deviations, as the store streams them (Welford's update).
struct Streamed {
  std::size_t count = 0;
  double sum = 0.0, mean = 0.0, squared_deviations = 0.0;
  void add(double x) {
    ++count;
    sum += x;
    const double deviation = x - mean;
    mean += deviation / static_cast<double>(count);
    squared_deviations += deviation * (x - mean);
  }
};

}  // namespace

TEST_CASE("Student's t 0.975 quantile against the published table and R", "[statistics]") {
  // Abramowitz & Stegun, Handbook of Mathematical Functions, table 26.10 (Q = 0.025 per tail),
  // given to 3 decimals.
  const std::vector<std::pair<std::size_t, double>> table{
      {1, 12.706}, {2, 4.303}, {3, 3.182}, {4, 2.776}, {5, 2.571}, {10, 2.228}, {19, 2.093}, {30, 2.042}, {120, 1.980}};
  for (const auto& [dof, expected] : table) {
    INFO("degrees of freedom " << dof);
    CHECK(student_t_975(dof) == Approx(expected).margin(5e-4));
  }
  // Beyond the exact values (1 to 30) the expansion, against
  // Rscript -e 'cat(sprintf("%.17g", qt(0.975, c(31, 40, 60, 100, 1000))))'.
  const std::vector<std::pair<std::size_t, double>> r{{31, 2.0395134463964082},
                                                      {40, 2.0210753903062733},
                                                      {60, 2.0002978220142595},
                                                      {100, 1.9839715185235516},
                                                      {1000, 1.9623390808264076}};
  for (const auto& [dof, expected] : r) {
    INFO("degrees of freedom " << dof);
    CHECK(student_t_975(dof) == Approx(expected).epsilon(2e-8));
  }
  // Towards the normal quantile: (z^3 + z) / (4 nu) = 2.4e-5 above it at nu = 100,000.
  CHECK(student_t_975(100000) == Approx(1.959964).epsilon(2e-5));
  CHECK_THROWS(student_t_975(0));
}

TEST_CASE("Mean estimate against R's t.test, streamed or from the values", "[statistics]") {
  // Rscript -e 'x <- c(0.91, 0.87, 0.95, 0.62, 0.78); options(digits = 17);
  //   print(c(mean(x), sd(x), sd(x) / sqrt(5), t.test(x)$conf.int))'
  const std::vector<double> x{0.91, 0.87, 0.95, 0.62, 0.78};
  Streamed streamed;
  for (const double value : x) streamed.add(value);
  const auto two_pass = mean_estimate(x);
  const auto one_pass = streamed_mean_estimate(streamed.count, streamed.sum, streamed.squared_deviations);
  for (const auto& estimate : {two_pass, one_pass}) {
    REQUIRE(estimate);
    CHECK(estimate->count == 5);
    CHECK(estimate->mean == Approx(0.82599999999999996).epsilon(1e-14));
    CHECK(*estimate->standard_deviation == Approx(0.13126309458488322).epsilon(1e-13));
    CHECK(*estimate->standard_error == Approx(0.058702640485756685).epsilon(1e-13));
    CHECK(*estimate->lower == Approx(0.66301534116113492).epsilon(1e-13));
    CHECK(*estimate->upper == Approx(0.98898465883886488).epsilon(1e-13));
  }

  CHECK_FALSE(mean_estimate(std::vector<double>{}));
  CHECK_FALSE(streamed_mean_estimate(0, 0.0, 0.0));
  const auto single = mean_estimate(std::vector<double>{0.7});
  REQUIRE(single);
  CHECK(single->mean == 0.7);
  CHECK_FALSE(single->standard_deviation);
  CHECK_FALSE(single->standard_error);
  CHECK_FALSE(single->lower);
}

TEST_CASE("Mean estimate: no digits lost to a mean large beside the spread", "[statistics]") {
  // Rscript -e 'options(digits = 17); print(sd(1e9 + c(0.1, 0.2, 0.3)))' gives 0.099999964237230898
  // (1e9 + 0.1 etc. are doubles up to 6e-8 away from the decimals). The textbook
  // sum(x^2) - sum(x)^2 / n loses all of it: 3e18 against a difference of 0.02.
  const std::vector<double> x{1e9 + 0.1, 1e9 + 0.2, 1e9 + 0.3};
  Streamed streamed;
  double squares = 0.0;
  for (const double value : x) {
    streamed.add(value);
    squares += value * value;
  }
  const double textbook = (squares - streamed.sum * streamed.sum / 3.0) / 2.0;
  CHECK(std::abs(textbook - 0.01) > 0.001);  // what a one-pass sum of squares would serve
  // Welford's running mean is rounded to the spacing of doubles at 1e9 (1.2e-7) at each step:
  // 1e-6 of the deviations of 0.1.
  const auto one_pass = streamed_mean_estimate(3, streamed.sum, streamed.squared_deviations);
  CHECK(*one_pass->standard_deviation == Approx(0.099999964237230898).epsilon(1e-6));
  CHECK(*mean_estimate(x)->standard_deviation == Approx(0.099999964237230898).epsilon(1e-7));
}

TEST_CASE("Ratio estimate: delta-method standard error of a case derived by hand", "[statistics]") {
  // Monomers a = (2, 0, 4) among fragments b = (1, 2, 3) in three cases: R = 6 / 6 = 1, residuals
  // a - R b = (1, -2, 1) with squares 6, mean(b) = 2: SE^2 = 6 / (3 * 2 * 2^2) = 1/4 (Cochran eq
  // 6.13), s = sqrt(6 / 2) / 2 = sqrt(3) / 2, interval 1 -/+ t(0.975, 2) / 2 = 1 -/+ 2.1513264.
  const auto ratio = ratio_estimate(std::vector<double>{2, 0, 4}, std::vector<double>{1, 2, 3});
  REQUIRE(ratio);
  CHECK(ratio->count == 3);
  CHECK(ratio->mean == 1.0);
  CHECK(*ratio->standard_error == Approx(0.5).epsilon(1e-15));
  CHECK(*ratio->standard_deviation == Approx(std::sqrt(3.0) / 2.0).epsilon(1e-15));
  CHECK(*ratio->lower == Approx(1.0 - 4.3026527297494619 / 2.0).epsilon(1e-15));
  CHECK(*ratio->upper == Approx(1.0 + 4.3026527297494619 / 2.0).epsilon(1e-15));

  const auto one_case = ratio_estimate(std::vector<double>{1}, std::vector<double>{4});
  REQUIRE(one_case);
  CHECK(one_case->mean == 0.25);
  CHECK_FALSE(one_case->standard_error);
  CHECK_FALSE(ratio_estimate(std::vector<double>{0, 0}, std::vector<double>{0, 0}));
  CHECK_THROWS(ratio_estimate(std::vector<double>{1}, std::vector<double>{1, 2}));
}

TEST_CASE("Mean estimate: 95 % coverage with 3 and 5 replicates, where 1.96 SE would not", "[statistics]") {
  // 4,000 samples from N(3, 2^2) for each n: the interval holds the true mean in 95 % of them
  // (binomial standard error 0.34 %; 4 of them allowed either way). The normal interval
  // mean -/+ 1.96 SE would cover 81 % at n = 3 and 88 % at n = 5 (R: 2 * pt(1.959964, c(2, 4)) - 1).
  std::mt19937_64 random(2026);
  std::normal_distribution<double> normal(3.0, 2.0);
  constexpr int kSamples = 4000;
  for (const std::size_t n : {3u, 5u}) {
    int covered = 0;
    for (int i = 0; i < kSamples; ++i) {
      std::vector<double> sample(n);
      for (auto& value : sample) value = normal(random);
      const auto estimate = mean_estimate(sample);
      covered += *estimate->lower <= 3.0 && 3.0 <= *estimate->upper;
    }
    INFO("n = " << n);
    CHECK(static_cast<double>(covered) / kSamples == Approx(0.95).margin(0.014));
  }
}

}  // namespace aerobreak
