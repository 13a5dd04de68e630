#pragma once
#include <cstdint>

#include "engine/core/vec3.hpp"

namespace aerobreak {

// A flat rigid wall of infinite extent: the plane through `point` with unit `normal` pointing into
// the space the particles occupy. Contacts use the particles' laws with R* = R_i, m* = m_i.
struct Wall {
  Vec3 point;
  Vec3 normal{0.0, 0.0, 1.0};
  std::uint16_t material = 0;
  bool adhesive = true;  // false: Hertz contact without adhesion (report figure 4)

  double gap(const Vec3& centre) const { return dot(centre - point, normal); }
};

}  // namespace aerobreak
