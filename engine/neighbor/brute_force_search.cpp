#include <algorithm>

#include "engine/neighbor/neighbor_search.hpp"

namespace aerobreak {
namespace {

template <class Space>
void all_pairs(const Space& separation, const std::vector<Vec3>& position, const std::vector<double>& radius,
               double margin, PairList& out) {
  const std::size_t n = position.size();
  out.row_start.assign(n + 1, 0);
  out.neighbor.clear();
  for (std::size_t i = 0; i < n; ++i) {
    out.row_start[i] = static_cast<std::uint32_t>(out.neighbor.size());
    for (std::size_t j = i + 1; j < n; ++j) {
      const double reach = radius[i] + radius[j] + margin;
      if (norm2(separation(position[j] - position[i])) < reach * reach)
        out.neighbor.push_back(static_cast<std::uint32_t>(j));
    }
  }
  out.row_start[n] = static_cast<std::uint32_t>(out.neighbor.size());
  out.contact.assign(out.neighbor.size(), -1);
}

}  // namespace

void BruteForceSearch::find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                                  PairList& out) {
  if (!box_) return all_pairs(OpenSpace{}, position, radius, margin, out);
  if (!position.empty()) box_->require_single_image(2.0 * *std::max_element(radius.begin(), radius.end()) + margin);
  all_pairs(PeriodicSpace(*box_), position, radius, margin, out);
}

}  // namespace aerobreak
