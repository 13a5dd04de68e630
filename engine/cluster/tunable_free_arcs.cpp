#include "engine/cluster/tunable_free_arcs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace aerobreak {

std::optional<double> free_angle(const std::vector<BlockedArc>& blocked, double u, double min_free_length) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  std::vector<std::pair<double, double>> spans;  // [begin, end) within [0, 2 pi)
  spans.reserve(2 * blocked.size());
  for (const BlockedArc& arc : blocked) {
    if (arc.half_width >= std::numbers::pi) return std::nullopt;
    if (!(arc.half_width > 0.0)) continue;
    double begin = std::fmod(arc.centre - arc.half_width, two_pi);
    if (begin < 0.0) begin += two_pi;
    const double end = begin + 2.0 * arc.half_width;
    if (end <= two_pi) {
      spans.emplace_back(begin, end);
    } else {
      spans.emplace_back(begin, two_pi);
      spans.emplace_back(0.0, end - two_pi);
    }
  }
  std::sort(spans.begin(), spans.end());

  // Free gaps between the merged blocked spans.
  std::vector<std::pair<double, double>> gaps;
  double reached = 0.0;
  for (const auto& [begin, end] : spans) {
    if (begin > reached) gaps.emplace_back(reached, begin);
    reached = std::max(reached, end);
  }
  if (reached < two_pi) gaps.emplace_back(reached, two_pi);

  double free_length = 0.0;
  for (const auto& [begin, end] : gaps) free_length += end - begin;
  if (free_length < min_free_length) return std::nullopt;

  double target = u * free_length;
  for (const auto& [begin, end] : gaps) {
    if (target < end - begin) return begin + target;
    target -= end - begin;
  }
  return 0.5 * (gaps.back().first + gaps.back().second);  // u * length rounded past the end
}

}  // namespace aerobreak
