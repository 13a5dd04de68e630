// A benchmark program, not a test: how many cases the adaptive boundary search needs to bring the
// 95 % interval of a crossing to a given width, against a uniform grid of speeds with equal
// replicates fitted the same way (docs/ADAPTIVE.md, "Cases saved"). Both on the seeded synthetic
// law (tests/support/synthetic_law.hpp).
//   build/tests/adaptive_search_bench [REPETITIONS]   (default 100)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "tests/support/search_simulation.hpp"

namespace {

using namespace aerobreak;
using namespace aerobreak::testing;

std::vector<double> grid_speeds(const BoundarySearchSpec& spec, int count) {
  std::vector<double> speeds;
  for (int k = 0; k < count; ++k)
    speeds.push_back(spec.from * std::pow(spec.to / spec.from, static_cast<double>(k) / (count - 1)));
  return speeds;
}

// Cases a uniform grid of `points` speeds needs: replicates are added to every speed at once, a
// round each, until the search's stopping rule finds the crossing (the same fit, the same
// confirmation on the replicates before the last, the same minimum of results); 0 when
// `max_replicates` do not suffice.
int grid_cases(const BoundarySearchSpec& spec, int points, std::uint64_t seed, int max_replicates) {
  SimulatedOutcomes outcomes(SyntheticLaw{}, 0.001, seed);
  std::vector<SearchObservation> observations;
  const auto speeds = grid_speeds(spec, points);
  for (int r = 1; r <= max_replicates; ++r) {
    for (const double v : speeds) observations.push_back(outcomes.at(v, r - 1));
    if (estimate_crossings(spec, observations, round_context(seed, 0, r, points * r))[0].found) return points * r;
  }
  return 0;
}

struct Summary {
  double mean = 0.0;
  double median = 0.0;
  int reached = 0;
};

Summary summarise(std::vector<int> cases) {
  Summary s;
  std::vector<int> reached;
  for (const int c : cases)
    if (c > 0) reached.push_back(c);
  s.reached = static_cast<int>(reached.size());
  if (reached.empty()) return s;
  std::sort(reached.begin(), reached.end());
  for (const int c : reached) s.mean += c;
  s.mean /= static_cast<double>(reached.size());
  s.median = reached[reached.size() / 2];
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const int repetitions = argc > 1 ? std::atoi(argv[1]) : 100;
  const SyntheticLaw law;
  std::printf(
      "synthetic law: P(break-up) = L((ln v - ln %.3g) / %.3g); search range %.3g-%.3g d/tau, "
      "%d repetitions\n\n",
      law.break_up_speed, law.spread, 0.005, 0.3, repetitions);
  std::printf("%-14s %-26s %-30s %-10s\n", "relative width", "adaptive: mean (median) n",
              "best uniform grid: mean (median) n", "ratio");
  for (const double width : {0.5, 0.3, 0.2}) {
    const auto spec = speed_search(width, 5000);
    std::vector<int> adaptive;
    for (int r = 0; r < repetitions; ++r) {
      const auto search = simulate_search(spec, law, 0.001, 5000 + static_cast<std::uint64_t>(r));
      adaptive.push_back(search.final.state == GroupState::converged ? search.cases : 0);
    }
    const Summary a = summarise(adaptive);
    Summary best;
    int best_points = 0;
    for (const int points : {6, 8, 12, 16, 24, 32}) {
      std::vector<int> grid;
      for (int r = 0; r < repetitions; ++r)
        grid.push_back(grid_cases(spec, points, 9000 + static_cast<std::uint64_t>(r), 400));
      const Summary g = summarise(grid);
      std::printf("  grid of %2d speeds, width %.2f: mean %.0f, median %.0f cases (%d of %d reached it)\n", points,
                  width, g.mean, g.median, g.reached, repetitions);
      if (g.reached == repetitions && (best_points == 0 || g.mean < best.mean)) best = g, best_points = points;
    }
    std::printf("%-14.2f %6.0f (%4.0f) %3d/%-3d        %2d speeds: %6.0f (%4.0f)           %.2f\n\n", width, a.mean,
                a.median, a.reached, repetitions, best_points, best.mean, best.median,
                best.mean > 0 ? a.mean / best.mean : 0.0);
  }
  return 0;
}
