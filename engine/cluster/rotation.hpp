#pragma once
#include "engine/core/vec3.hpp"

namespace aerobreak {

// A proper rotation stored as a 3x3 matrix (rows), built from a unit quaternion (w, x, y, z).
struct Rotation {
  Vec3 row0{1.0, 0.0, 0.0};
  Vec3 row1{0.0, 1.0, 0.0};
  Vec3 row2{0.0, 0.0, 1.0};

  Vec3 apply(const Vec3& v) const { return {dot(row0, v), dot(row1, v), dot(row2, v)}; }

  static Rotation from_unit_quaternion(double w, double x, double y, double z) {
    return {{1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)},
            {2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)},
            {2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)}};
  }
};

}  // namespace aerobreak
