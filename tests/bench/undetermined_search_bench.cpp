// A benchmark program, not a test: what cases that end undetermined cost the adaptive search, with
// the design that ignores them (the design before) and the one that weighs each candidate by the
// chance of a determined outcome there (docs/ADAPTIVE.md, "Undetermined outcomes"). The seeded
// synthetic law (tests/support/synthetic_law.hpp) and one with a transition twice as wide, with the
// cases below the range's 10 % quantile (or above its 90 % one, or both) ending undetermined with a
// chance of 0.9; the same seeds for both designs.
//   build/tests/undetermined_search_bench [SEARCHES]   (default 200)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/support/search_simulation.hpp"

namespace {

using namespace aerobreak;
using namespace aerobreak::testing;

struct Tally {
  double determined = 0.0, undetermined = 0.0;
  int converged = 0, covered = 0, searches = 0;
};

Tally run(const BoundarySearchSpec& spec, const SyntheticLaw& law, const UndeterminedBand& band,
          UndeterminedWeighting weighting, int searches) {
  const double truth = law.crossing("break-up", 0.5);
  Tally t;
  for (int s = 0; s < searches; ++s) {
    const auto search = simulate_search(spec, law, 0.001, 1000 + static_cast<std::uint64_t>(s), band, weighting);
    const auto& e = search.final.estimates[0];
    ++t.searches;
    t.determined += search.cases - search.undetermined;
    t.undetermined += search.undetermined;
    t.converged += search.final.state == GroupState::converged;
    t.covered += e.lower && e.upper && *e.lower <= truth && truth <= *e.upper;
  }
  return t;
}

void report(const std::string& band, const std::string& design, const Tally& t) {
  const double n = t.searches;
  const double rate = t.covered / n;
  std::printf("%-28s %-22s %6.1f %6.1f %6.1f   %4d/%-4d   %5.1f %% (SE %.1f %%)\n", band.c_str(), design.c_str(),
              (t.determined + t.undetermined) / n, t.determined / n, t.undetermined / n, t.converged, t.searches,
              100.0 * rate, 100.0 * std::sqrt(0.95 * 0.05 / n));
}

}  // namespace

int main(int argc, char** argv) {
  const int searches = argc > 1 ? std::atoi(argv[1]) : 200;
  const auto spec = speed_search(0.3, 600);
  const double low = spec.from * std::pow(spec.to / spec.from, 0.1);
  const double high = spec.from * std::pow(spec.to / spec.from, 0.9);
  const std::vector<std::pair<std::string, UndeterminedBand>> bands{
      {"none undetermined", {}},
      {"below " + std::to_string(low).substr(0, 6) + ", chance 0.9", {low, INFINITY, 0.9}},
      {"above " + std::to_string(high).substr(0, 6) + ", chance 0.9", {0.0, high, 0.9}},
      {"both, chance 0.9", {low, high, 0.9}},
  };
  SyntheticLaw wide;
  wide.spread = 0.5;  // a transition twice as wide: the range spans 8 of its logistic scales, not 16
  for (const auto& law : {SyntheticLaw{}, wide}) {
    std::printf(
        "%d seeded searches for v50 = %.3g, logistic scale %.2f in ln v; range %.3g-%.3g, relative width 0.3, "
        "budget %d; mean cases a search\n",
        searches, law.break_up_speed, law.spread, spec.from, spec.to, spec.budget);
    std::printf("%-28s %-22s %6s %6s %6s   %-9s   %s\n", "undetermined", "design", "cases", "determ", "undet",
                "converged", "95 % interval holds v50");
    for (const auto& [name, band] : bands) {
      report(name, "ignores undetermined", run(spec, law, band, UndeterminedWeighting::none, searches));
      report(name, "weighs by chance", run(spec, law, band, UndeterminedWeighting::by_chance, searches));
    }
    std::printf("\n");
  }
  return 0;
}
