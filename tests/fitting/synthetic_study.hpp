#pragma once
// Synthetic studies for the statistics tests: outcomes drawn from a known logistic law, seeded,
// with a generator whose numbers do not depend on the standard library's distributions.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "orchestrator/fitting/case_outcome.hpp"

namespace aerobreak::synthetic {

// Uniform on [0, 1) from the top 53 bits of a 64-bit Mersenne twister (defined by the standard).
class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : engine_(seed) {}
  double operator()() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

struct LogisticLaw {
  double v50 = 0.05;   // speed of P(break-up) = 1/2
  double slope = 3.0;  // in log speed
  double probability(double speed) const { return 1.0 / (1.0 + std::exp(-slope * (std::log(speed) - std::log(v50)))); }
};

// `speeds` grid points on the axis "impact_speed" (and one more axis "primaries" = N), `replicates`
// cases each: break-up with the law's probability, stick otherwise.
inline CaseOutcomeTable draw_study(const LogisticLaw& law, const std::vector<double>& speeds, int replicates,
                                   Uniform& uniform, double primaries = 32) {
  CaseOutcomeTable table;
  table.axes = {"impact_speed", "primaries"};
  for (const double speed : speeds) {
    table.grid_points.push_back({{"impact_speed", speed}, {"primaries", primaries}});
    for (int r = 0; r < replicates; ++r) {
      CaseOutcome c;
      c.grid_point = table.grid_points.size() - 1;
      c.outcome = uniform() < law.probability(speed) ? ImpactOutcome::break_up : ImpactOutcome::stick;
      c.primaries = static_cast<std::int64_t>(primaries);
      table.cases.push_back(c);
    }
  }
  return table;
}

inline std::vector<double> log_speeds(double from, double to, int count) {
  std::vector<double> speeds;
  for (int i = 0; i < count; ++i) speeds.push_back(from * std::pow(to / from, i / (count - 1.0)));
  return speeds;
}

}  // namespace aerobreak::synthetic
