#include "engine/impact/outcome.hpp"

#include <cstdio>
#include <stdexcept>

namespace aerobreak {

std::string to_string(ImpactOutcome outcome) {
  switch (outcome) {
    case ImpactOutcome::stick: return "stick";
    case ImpactOutcome::bounce: return "bounce";
    case ImpactOutcome::break_up: return "break-up";
    case ImpactOutcome::undetermined: return "undetermined";
  }
  return "undetermined";
}

Classification classify(const std::vector<Fragment>& fragments, bool settled, double largest_fragment_share) {
  if (!(largest_fragment_share > 0.0 && largest_fragment_share <= 1.0))
    throw std::invalid_argument("classify: largest_fragment_share must be in (0, 1]");
  Classification c;
  std::size_t primaries = 0;
  for (const Fragment& f : fragments) primaries += f.size;
  if (fragments.empty() || primaries == 0) {
    c.reason = "no primaries";
    return c;
  }
  const Fragment& largest = fragments.front();
  c.largest_fragment_share = static_cast<double>(largest.size) / static_cast<double>(primaries);
  char share[160];
  std::snprintf(share, sizeof share, "the largest fragment holds %zu of %zu primaries (%.4g, threshold %.4g)",
                largest.size, primaries, c.largest_fragment_share, largest_fragment_share);
  if (!settled) {
    c.reason = "the time limit came before the outcome settled";
    return c;
  }
  if (c.largest_fragment_share < largest_fragment_share) {
    c.outcome = ImpactOutcome::break_up;
    c.reason = std::string(share) + ": below the threshold";
  } else if (largest.on_wall()) {
    c.outcome = ImpactOutcome::stick;
    c.reason = std::string(share) + " and touches the wall";
  } else if (largest.normal_velocity > 0.0) {
    c.outcome = ImpactOutcome::bounce;
    c.reason = std::string(share) + " and moves away from the wall";
  } else {
    c.reason = std::string(share) + " but neither touches the wall nor moves away from it";
  }
  return c;
}

}  // namespace aerobreak
