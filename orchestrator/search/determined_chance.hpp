#pragma once
#include <vector>

#include "orchestrator/search/boundary_search.hpp"

namespace aerobreak {

// The chance q that a case at each of `values` (axis values) ends with a determined outcome, from
// the group's own results: over the results within half a round-0 spacing of the value in the
// model's scale (at least one candidate step), q = (determined + 1) / (results + 1), and 1 where
// there are none. A case that ends undetermined (the impact hit its time limit) is left out of the
// fit and informs nothing, so the design weights each candidate's information by q
// (docs/ADAPTIVE.md, "Undetermined outcomes"). q is exactly 1 wherever no undetermined result lies
// near, so there the design is the one that ignores undetermined outcomes.
std::vector<double> determined_chances(const BoundarySearchSpec& spec,
                                       const std::vector<SearchObservation>& observations,
                                       const std::vector<double>& values);

// The half-width of the window determined_chances pools over, in dose units.
double determined_window(const BoundarySearchSpec& spec);

}  // namespace aerobreak
