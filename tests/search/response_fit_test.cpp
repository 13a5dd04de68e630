// The search's logistic fit is Firth's penalised likelihood on every sample, not maximum likelihood
// where that exists (docs/ADAPTIVE.md, "The fit and the interval"). The reference values come from
// tests/search/firth_reference.py, Newton's method on Firth's modified score in plain Python
// (python3 tests/search/firth_reference.py), on the data below:
//   firth -0.216975698383 2.11117978135
//   ml    -0.265610568509 2.57989996707
#include <catch2/catch.hpp>

#include "orchestrator/search/response_fit.hpp"
#include "tests/support/search_simulation.hpp"

namespace aerobreak::testing {

TEST_CASE("The search fits Firth's penalised likelihood also where maximum likelihood exists", "[search]") {
  // Five speeds, five cases each, break-ups 0, 1, 2, 4, 5: the outcomes overlap, so a maximum
  // likelihood estimate exists, and its slope is a fifth steeper than Firth's.
  const BoundarySearchSpec spec = speed_search(0.3, 300);
  const std::vector<double> speeds{0.01, 0.02, 0.04, 0.08, 0.16};
  const std::vector<int> break_ups{0, 1, 2, 4, 5};
  std::vector<SearchObservation> observations;
  for (std::size_t i = 0; i < speeds.size(); ++i)
    for (int c = 0; c < 5; ++c) observations.push_back({speeds[i], c < break_ups[i] ? "break-up" : "stick", 0});
  const ResponseFit fit = fit_response(spec, observations, "break-up");
  REQUIRE(fit.overlap == Overlap::overlapping);
  REQUIRE(fit.fit);
  // Newton converges quadratically: a last step below 1e-10 leaves both far within 1e-8.
  CHECK(fit.fit->coefficients[0] == Approx(-0.216975698383).epsilon(1e-8));
  CHECK(fit.fit->coefficients[1] == Approx(2.11117978135).epsilon(1e-8));
  CHECK(crossing(spec, fit, 0.5).fit == "firth");
}

}  // namespace aerobreak::testing
