#include "orchestrator/search/determined_chance.hpp"

#include <algorithm>
#include <cmath>

namespace aerobreak {

double determined_window(const BoundarySearchSpec& spec) {
  const double span = search_dose(spec, spec.to) - search_dose(spec, spec.from);
  // Round 0's values are spread evenly over the range, so windows of half their spacing around
  // them tile it: from round 0 on every candidate has a result to go by. At least one candidate
  // step, so that the neighbours of a wasted case see it.
  const double round0 = span / static_cast<double>(spec.initial - 1);
  const double step = span / static_cast<double>(spec.resolution - 1);
  return std::max(0.5 * round0, step);
}

std::vector<double> determined_chances(const BoundarySearchSpec& spec,
                                       const std::vector<SearchObservation>& observations,
                                       const std::vector<double>& values) {
  const double window = determined_window(spec);
  std::vector<double> chances;
  chances.reserve(values.size());
  for (const double value : values) {
    const double dose = search_dose(spec, value);
    double results = 0.0, determined = 0.0;
    for (const auto& o : observations)
      if (std::abs(search_dose(spec, o.value) - dose) <= window) {
        results += 1.0;
        determined += o.outcome != "undetermined" ? 1.0 : 0.0;
      }
    // The posterior mean of q under a prior worth one determined case: 1 until an undetermined
    // result is seen, then falling as they accumulate (1/2 after one, 1/3 after two, ...).
    chances.push_back((determined + 1.0) / (results + 1.0));
  }
  return chances;
}

}  // namespace aerobreak
