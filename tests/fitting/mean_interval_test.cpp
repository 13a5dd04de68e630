// The Student-t quantile against published tables, and the mean's interval covering on synthetic
// data (the Wilson interval: proportion_test.cpp).
#include <catch2/catch.hpp>

#include <random>

#include "orchestrator/fitting/mean_interval.hpp"

namespace aerobreak {

TEST_CASE("Student's t 0.975 quantile against the published table", "[statistics]") {
  // Abramowitz & Stegun, Handbook of Mathematical Functions, table 26.10 (Q = 0.025 per tail).
  const std::vector<std::pair<std::size_t, double>> table{
      {1, 12.706}, {2, 4.303}, {3, 3.182}, {4, 2.776}, {5, 2.571}, {10, 2.228}, {19, 2.093}, {30, 2.042}, {120, 1.980}};
  for (const auto& [dof, expected] : table) {
    INFO("degrees of freedom " << dof);
    // 5e-4 is the table's rounding; 0.12 % the expansion's own error at 3 degrees of freedom.
    CHECK(student_t_975(dof) == Approx(expected).epsilon(1.3e-3).margin(5e-4));
  }
  // Towards the normal quantile: (z^3 + z) / (4 nu) = 2.4e-5 above it at nu = 100,000.
  CHECK(student_t_975(100000) == Approx(1.959964).epsilon(2e-5));
  CHECK_THROWS(student_t_975(0));
}

TEST_CASE("Mean interval: moments of a small sample, and 95 % coverage on normal samples", "[statistics]") {
  // 1, 2, 3, 4: mean 2.5, s = sqrt(5/3), half-width t(3) s / 2 = 3.1824 * 1.2910 / 2 = 2.0542
  // (within the expansion's 0.12 % at 3 degrees of freedom).
  const auto estimate = mean_interval(4, 10.0, 30.0);
  REQUIRE(estimate);
  CHECK(estimate->mean == 2.5);
  CHECK(*estimate->standard_deviation == Approx(std::sqrt(5.0 / 3.0)));
  CHECK(*estimate->upper - estimate->mean == Approx(2.0542).epsilon(1.3e-3));
  CHECK_FALSE(mean_interval(0, 0.0, 0.0));
  const auto single = mean_interval(1, 0.7, 0.49);
  CHECK(single->mean == Approx(0.7));
  CHECK_FALSE(single->lower);

  // 4,000 samples of 5 from N(3, 2^2): the interval holds the true mean in 95 % of them
  // (binomial standard error 0.34 %; 4 of them allowed either way).
  std::mt19937_64 random(2026);
  std::normal_distribution<double> normal(3.0, 2.0);
  constexpr int kSamples = 4000;
  int covered = 0;
  for (int i = 0; i < kSamples; ++i) {
    double sum = 0.0, squares = 0.0;
    for (int k = 0; k < 5; ++k) {
      const double x = normal(random);
      sum += x;
      squares += x * x;
    }
    const auto sample = mean_interval(5, sum, squares);
    covered += *sample->lower <= 3.0 && 3.0 <= *sample->upper;
  }
  CHECK(static_cast<double>(covered) / kSamples == Approx(0.95).margin(0.014));
}

}  // namespace aerobreak
