#pragma once
#include <cstddef>
#include <vector>

#include "engine/core/vec3.hpp"

namespace aerobreak {

// A cluster of primary spheres: positions and radii, in the caller's length unit (reduced units:
// primary diameter d = 1).
struct Cluster {
  std::vector<Vec3> position;
  std::vector<double> radius;

  std::size_t size() const { return position.size(); }
};

}  // namespace aerobreak
