#pragma once
#include <limits>

#include "engine/core/vec3.hpp"

namespace aerobreak {

// Where a fragment can be from now on (the fates-fixed rule, docs/IMPACT.md section 4): within its
// bounding sphere about a centre that moves on a straight line until `stop` (time from now), and
// after it within a ball about a point that moves on from there at `after`, the ball growing at
// `spread`: a fragment that lands on an adhesive wall stays where it got to (both 0); one that
// bounces off a wall without adhesion leaves on a course known only within bounds.
struct FragmentPath {
  Vec3 centre;
  Vec3 velocity;
  double radius = 0.0;
  double stop = std::numeric_limits<double>::infinity();
  Vec3 after;
  double spread = 0.0;
};

// Whether two fragments on these paths can touch at some time from now on: whether the distance of
// their centres can fall to the sum of their radii (each the bounding radius, plus its ball).
bool paths_can_meet(const FragmentPath& a, const FragmentPath& b);

}  // namespace aerobreak
