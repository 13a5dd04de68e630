#pragma once
#include <vector>

#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// Per grid point: outcome probabilities among the determined cases (Wilson 95 %), the means of the
// retained mass fraction, the restitution of the bounces, the damage ratio and the energy per
// contact (each a MeanEstimate: mean_estimate.hpp), and the re-entrained fragments. A grid point whose
// cases are all undetermined has n = 0 and no estimates, never a guess.
std::vector<GridPointSummary> summarise_grid_points(const CaseOutcomeTable& table);

// Re-entrained fragment statistics of a set of cases (docs/CORRELATIONS.md, "Fragments").
FragmentStatistics fragment_statistics(const std::vector<const CaseOutcome*>& cases);

}  // namespace aerobreak
