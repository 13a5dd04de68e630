#include "engine/growth/cluster_proximity.hpp"

#include <algorithm>
#include <limits>

namespace aerobreak {

GroupProximitySearch::GroupProximitySearch(const PeriodicBox& box, double search_gap, std::size_t sphere_limit)
    : box_(box), search_gap_(search_gap), sphere_limit_(sphere_limit), search_(box) {}

GroupProximity GroupProximitySearch::find(const std::vector<Vec3>& position, const std::vector<double>& radius,
                                          const std::vector<std::uint32_t>& group, std::size_t groups,
                                          const std::vector<BoundingSphere>& spheres, double close_gap) {
  search_.find_pairs(position, radius, search_gap_, pairs_);
  GroupProximity result;
  result.gap.assign(groups, std::numeric_limits<double>::infinity());
  // Smallest gap per pair of groups that has particle pairs within the search gap.
  std::vector<std::pair<std::uint64_t, double>> pair_gaps;
  for (std::uint32_t i = 0; i < pairs_.particles(); ++i)
    for (std::uint32_t k = pairs_.row_start[i]; k < pairs_.row_start[i + 1]; ++k) {
      const std::uint32_t j = pairs_.neighbor[k];
      const std::uint32_t a = std::min(group[i], group[j]), b = std::max(group[i], group[j]);
      if (a == b) continue;
      const double gap = norm(box_.minimum_image(position[j] - position[i])) - radius[i] - radius[j];
      pair_gaps.emplace_back((static_cast<std::uint64_t>(a) << 32) | b, gap);
    }
  std::sort(pair_gaps.begin(), pair_gaps.end());
  std::vector<std::vector<std::uint32_t>> found(groups);
  for (std::size_t k = 0; k < pair_gaps.size(); ++k) {
    if (k > 0 && pair_gaps[k].first == pair_gaps[k - 1].first) continue;  // sorted: the first is the smallest
    const auto a = static_cast<std::uint32_t>(pair_gaps[k].first >> 32);
    const auto b = static_cast<std::uint32_t>(pair_gaps[k].first & 0xffffffffu);
    const double gap = pair_gaps[k].second;
    result.gap[a] = std::min(result.gap[a], gap);
    result.gap[b] = std::min(result.gap[b], gap);
    found[a].push_back(b);
    found[b].push_back(a);
    if (gap < close_gap) result.close.emplace_back(a, b);
  }
  // Pairs of groups not found are at least the search gap apart, and at least their spheres' gap.
  const bool spheres_known =
      spheres.size() == groups && groups <= sphere_limit_ &&
      std::all_of(spheres.begin(), spheres.end(), [](const BoundingSphere& s) { return s.reach >= 0.0; });
  for (std::uint32_t a = 0; a < groups; ++a) {
    if (!spheres_known) {
      if (groups > 1 && found[a].size() + 1 < groups) result.gap[a] = std::min(result.gap[a], search_gap_);
      continue;
    }
    std::sort(found[a].begin(), found[a].end());
    for (std::uint32_t b = 0; b < groups; ++b) {
      if (b == a || std::binary_search(found[a].begin(), found[a].end(), b)) continue;
      const double apart =
          norm(box_.minimum_image(spheres[b].centre - spheres[a].centre)) - spheres[a].reach - spheres[b].reach;
      result.gap[a] = std::min(result.gap[a], std::max(search_gap_, apart));
    }
  }
  return result;
}

}  // namespace aerobreak
