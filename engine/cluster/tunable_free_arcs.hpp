#pragma once
#include <optional>
#include <vector>

namespace aerobreak {

// An open arc of a circle, (centre - half_width, centre + half_width) in radians; a half-width of
// pi or more covers the whole circle.
struct BlockedArc {
  double centre = 0.0;
  double half_width = 0.0;
};

// The angle at fraction u in [0, 1) of the free part of the circle (what no arc covers), measured
// along the free angles in increasing order from 0: with u uniform on [0, 1) the angle is uniform
// over the free set. Empty when the free set is shorter than min_free_length (radians).
std::optional<double> free_angle(const std::vector<BlockedArc>& blocked, double u, double min_free_length);

}  // namespace aerobreak
