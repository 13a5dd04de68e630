// The Wilson score interval against values computed by hand from its formula, and its limits.
#include <catch2/catch.hpp>

#include "orchestrator/fitting/proportion.hpp"

namespace aerobreak {

TEST_CASE("Wilson interval: textbook values and edge cases", "[statistics]") {
  // k = 5, n = 10, z = 1.96: centre 0.5, half-width 1.96 sqrt(0.025 + 0.009604) / 1.38416 = 0.2366.
  const auto half = wilson_interval(5, 10);
  REQUIRE(half);
  CHECK(half->probability == 0.5);
  CHECK(half->lower == Approx(0.2366).margin(1e-4));
  CHECK(half->upper == Approx(0.7634).margin(1e-4));
  // k = 0 of n = 10: lower bound 0, upper z^2/(n + z^2) = 0.2775.
  const auto none = wilson_interval(0, 10);
  CHECK(none->lower == Approx(0.0).margin(1e-12));
  CHECK(none->upper == Approx(3.8415 / 13.8415).margin(1e-4));
  const auto all = wilson_interval(10, 10);
  CHECK(all->upper == Approx(1.0).margin(1e-12));
  CHECK(all->lower == Approx(1.0 - 3.8415 / 13.8415).margin(1e-4));
  CHECK_FALSE(wilson_interval(0, 0));
  CHECK_THROWS(wilson_interval(3, 2));
}

TEST_CASE("Wilson interval: the bound at k = 0 is exactly 0 and at k = n exactly 1, not round-off", "[statistics]") {
  // Centre and half-width are equal in exact arithmetic there; in doubles their difference was
  // 5.55e-17 for k = 0 of n = 20, printed in the outcome table.
  for (std::size_t n = 1; n <= 1000; ++n) {
    INFO("n = " << n);
    CHECK(wilson_interval(0, n)->lower == 0.0);
    CHECK(wilson_interval(n, n)->upper == 1.0);
  }
}

TEST_CASE("Wilson interval narrows as 1/sqrt(n) at a fixed proportion", "[statistics]") {
  const auto small = wilson_interval(30, 100);
  const auto large = wilson_interval(3000, 10000);
  const double ratio = (small->upper - small->lower) / (large->upper - large->lower);
  CHECK(ratio == Approx(10.0).epsilon(0.02));
}

}  // namespace aerobreak
