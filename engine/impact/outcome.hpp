#pragma once
#include <string>
#include <vector>

#include "engine/impact/fragments.hpp"

namespace aerobreak {

enum class ImpactOutcome { stick, bounce, break_up, undetermined };

// "stick", "bounce", "break-up", "undetermined" (the names results use).
std::string to_string(ImpactOutcome outcome);

struct Classification {
  ImpactOutcome outcome = ImpactOutcome::undetermined;
  double largest_fragment_share = 0.0;  // primaries in the largest fragment / all primaries
  std::string reason;                   // one sentence: which rule decided
};

// DESIGN.md "Impact and outcomes", applied to the fragments of a settled impact (`settled` false:
// undetermined, whatever the fragments look like):
//   break-up  the largest fragment holds less than `largest_fragment_share` of the primaries;
//   stick     otherwise, if the largest fragment touches the wall;
//   bounce    otherwise, if it has left the wall and moves away from it (normal velocity > 0);
//   undetermined in every other case.
// `fragments` must be largest first (as find_fragments returns them). The same rule re-applied to
// stored per-fragment data with another threshold gives the re-classified outcome.
Classification classify(const std::vector<Fragment>& fragments, bool settled, double largest_fragment_share = 0.9);

}  // namespace aerobreak
